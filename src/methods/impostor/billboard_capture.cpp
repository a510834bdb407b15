#include "methods/impostor/billboard_capture.h"

#include <algorithm>
#include <cmath>

namespace mirage {

namespace {

float angleBetween(const vec3& a, const vec3& b) {
  if (a == b) return 0.0f;
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

// A direction in the space of an object under `m` (its linear part undone), unit.
vec3 inObjectSpace(const mat4& m, const vec3& direction) {
  const vec3 d = glm::inverse(mat3(m)) * direction;
  const float length = glm::length(d);
  return length > 0.0f ? d / length : vec3(0.0f);
}

}  // namespace

BillboardCapture::BillboardCapture(int size)
    : size_(size),
      depth_(gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, size, size)),
      diffuse_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                              "methods/impostor/capture_diffuse.frag")),
      reflector_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                                "methods/impostor/capture_reflector.frag")) {
  fbo_.attachDepth(depth_);
}

BillboardCapture::Captured BillboardCapture::capturedNow(const GpuScene& gpu,
                                                         const BillboardSpec& b) const {
  Captured c;
  c.valid = true;
  c.corner = b.corner;
  c.edge_u = b.edge_u;
  c.edge_v = b.edge_v;
  c.object = gpu.instanceMatrix(b.object);
  c.seen_from = inObjectSpace(c.object, b.camera.position - b.camera.target);
  c.shape = gpu.shapeVersion(b.object);
  if (b.kind != BillboardSpec::Kind::kReflective) {
    const Light& light = gpu.light();
    c.light_dir = inObjectSpace(c.object, light.direction);
    c.light_color = light.color;
    c.ambient = light.ambient;
  }
  c.frame = frame_;
  return c;
}

// The drift of a billboard shown from capture `c` against a capture made now: the turn of the
// direction its object is seen from (and of the light, for a diffuse one, in the object's
// frame), and the change of its quad's size in texels. A reflective billboard's world-space
// surface points and normals are carried with its reflector's motion (BillboardCarry), so its
// reflector's turn is measured as a diffuse billboard's object's is.
Drift BillboardCapture::drift(const GpuScene& gpu, const BillboardSpec& b,
                              const Captured& c) const {
  Drift d;
  d.age = frame_ - c.frame;
  const Captured now = capturedNow(gpu, b);
  d.angle =
      std::max(angleBetween(now.seen_from, c.seen_from), angleBetween(now.light_dir, c.light_dir));
  d.unmeasured =
      now.shape != c.shape || now.light_color != c.light_color || now.ambient != c.ambient;
  const mat3 carry = mat3(now.object) * glm::inverse(mat3(c.object));
  const float carried = glm::length(carry * c.edge_u);
  const float texel = carried / float(size_);
  d.texels = texel > 0.0f ? std::abs(glm::length(b.edge_u) - carried) / texel : 0.0f;
  return d;
}

void BillboardCapture::allocate(const BillboardSet& set) {
  const int levels = gpu::Texture::fullMipLevels(size_);
  const int surfaces = std::max(set.surface_layers, 1);
  const int positions = std::max(set.position_layers, 1);
  bool fresh = false;
  if (surfaces_.layers() != surfaces) {
    surfaces_ = gpu::Texture::create2DArray(GL_RGBA16F, size_, size_, surfaces, levels);
    fresh = true;
  }
  if (positions_.layers() != positions) {
    positions_ = gpu::Texture::create2DArray(GL_RGBA32F, size_, size_, positions, 1);
    fresh = true;
  }
  if (fresh || captured_.size() != set.billboards.size())
    captured_.assign(set.billboards.size(), Captured{});
}

int BillboardCapture::update(GpuScene& gpu, ScenePasses& passes, BillboardSet& set,
                             const FrameSettings& settings, const RecapturePolicy& policy,
                             const std::vector<Drift>& others, std::vector<bool>* others_due) {
  allocate(set);
  const size_t n = set.billboards.size();
  std::vector<Drift> drift(n);
  for (size_t i = 0; i < n; ++i) {
    if (!captured_[i].valid)
      drift[i].invalid = true;
    else
      drift[i] = this->drift(gpu, set.billboards[i], captured_[i]);
  }
  drift.insert(drift.end(), others.begin(), others.end());
  std::vector<int> due = chooseRecaptures(drift, policy);
  if (others_due) others_due->assign(others.size(), false);
  const size_t captures = due.size();
  std::erase_if(due, [&](int i) {
    if (size_t(i) < n) return false;
    if (others_due) (*others_due)[size_t(i) - n] = true;
    return true;
  });
  drift.resize(n);
  std::vector<bool> fresh(n, false);
  for (int i : due) {
    capture(gpu, passes, set.billboards[size_t(i)], settings);
    captured_[size_t(i)] = capturedNow(gpu, set.billboards[size_t(i)]);
    fresh[size_t(i)] = true;
  }
  // The others show their old captures, carried by their objects' motion since.
  drift.insert(drift.end(), others.begin(), others.end());
  pending_ =
      int(chooseRecaptures(drift, RecapturePolicy{policy.angle_degrees, policy.texels, 0}).size()) -
      int(captures);
  largest_drift_ = 0.0f;
  for (size_t i = 0; i < set.billboards.size(); ++i) {
    if (fresh[i]) continue;
    BillboardSpec& b = set.billboards[i];
    const Captured& c = captured_[i];
    const mat4 carry = gpu.instanceMatrix(b.object) * glm::inverse(c.object);
    b.corner = transformPoint(carry, c.corner);
    b.edge_u = mat3(carry) * c.edge_u;
    b.edge_v = mat3(carry) * c.edge_v;
    b.carry = carry;
    largest_drift_ = std::max(largest_drift_, glm::degrees(drift[i].angle));
  }
  // The captured layers' mip chains: all at once when most are new.
  if (due.size() * 2 > size_t(surfaces_.layers()))
    surfaces_.generateMipmaps();
  else
    for (int i : due) surfaces_.generateMipmaps(set.billboards[size_t(i)].layer, 1);
  captures_ += long(due.size());
  ++frame_;
  return int(due.size());
}

void BillboardCapture::capture(GpuScene& gpu, ScenePasses& passes, const BillboardSpec& b,
                               const FrameSettings& settings) {
  const bool reflective = b.kind == BillboardSpec::Kind::kReflective;
  if (reflective) {
    fbo_.attachColor(0, surfaces_, 0, b.layer);
    fbo_.attachColor(2, positions_, 0, b.position_layer);
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fbo_.id(), 3, buffers);
  } else {
    fbo_.attachColor(0, surfaces_, 0, b.layer);
    fbo_.setDrawBuffers(1);
  }
  fbo_.checkComplete("billboard capture");
  fbo_.bind();
  glViewport(0, 0, size_, size_);
  const float clear[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, clear);
  if (reflective) glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 2, clear);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far_depth);
  passes.begin(View(b.camera, {size_, size_}), settings);
  (reflective ? reflector_program_ : diffuse_program_).use();
  gpu.draw(b.object);
  for (int member : b.members) gpu.draw(member);
}

}  // namespace mirage
