#include "methods/impostor/billboard_capture.h"

namespace mirage {

namespace {

bool sameCamera(const CameraDesc& a, const CameraDesc& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.fov_y_degrees == b.fov_y_degrees && a.near_plane == b.near_plane &&
         a.far_plane == b.far_plane;
}

}  // namespace

bool BillboardCapture::Key::operator==(const Key& o) const {
  return sameCamera(camera, o.camera) && object == o.object && shape == o.shape &&
         light_dir == o.light_dir && light_color == o.light_color && ambient == o.ambient;
}

BillboardCapture::BillboardCapture(int size)
    : size_(size),
      depth_(gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, size, size)),
      diffuse_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                              "methods/impostor/capture_diffuse.frag")),
      reflector_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                                "methods/impostor/capture_reflector.frag")) {
  fbo_.attachDepth(depth_);
}

BillboardCapture::Key BillboardCapture::keyOf(const GpuScene& gpu, const BillboardSpec& b) const {
  Key key{b.camera, gpu.instanceMatrix(b.object), gpu.shapeVersion(b.object)};
  if (b.kind != BillboardSpec::Kind::kReflective) {
    const Light& light = gpu.light();
    key.light_dir = light.direction;
    key.light_color = light.color;
    key.ambient = light.ambient;
  }
  return key;
}

void BillboardCapture::allocate(const BillboardSet& set) {
  const int levels = gpu::Texture::fullMipLevels(size_);
  const int surfaces = std::max(set.surface_layers, 1);
  const int positions = std::max(set.position_layers, 1);
  if (surfaces_.layers() != surfaces)
    surfaces_ = gpu::Texture::create2DArray(GL_RGBA16F, size_, size_, surfaces, levels);
  if (positions_.layers() != positions)
    positions_ = gpu::Texture::create2DArray(GL_RGBA32F, size_, size_, positions, 1);
  if (keys_.size() != set.billboards.size()) {
    keys_.assign(set.billboards.size(), Key{});
    valid_.assign(set.billboards.size(), false);
  }
}

int BillboardCapture::update(GpuScene& gpu, ScenePasses& passes, const BillboardSet& set,
                             const FrameSettings& settings) {
  allocate(set);
  int captured = 0;
  bool surfaces_changed = false;
  for (size_t i = 0; i < set.billboards.size(); ++i) {
    const BillboardSpec& b = set.billboards[i];
    Key key = keyOf(gpu, b);
    if (valid_[i] && keys_[i] == key) continue;
    capture(gpu, passes, b, settings);
    keys_[i] = key;
    valid_[i] = true;
    ++captured;
    surfaces_changed = true;
  }
  if (surfaces_changed) surfaces_.generateMipmaps();
  captures_ += captured;
  return captured;
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
}

}  // namespace mirage
