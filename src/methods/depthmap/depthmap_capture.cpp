#include "methods/depthmap/depthmap_capture.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/timer.h"

namespace mirage {

namespace {

bool sameSpec(const DepthMapSpec& a, const DepthMapSpec& b) {
  return a.instance == b.instance && a.members == b.members && a.centre == b.centre &&
         a.from == b.from && a.up == b.up && a.radius == b.radius;
}

}  // namespace

DepthMapCapture::DepthMapCapture(const DepthMapOptions& options, const SrdmSettings& srdm,
                                 SrdmBuilder builder)
    : options_(options),
      srdm_settings_(srdm),
      scratch_depth_(gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, options.size, options.size)),
      program_(gpu::Program::graphics("render/shaders/scene.vert",
                                      "methods/impostor/capture_diffuse.frag")),
      normal_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                             "methods/depthmap/capture_normal.frag")) {
  // The builder's own check, before anything is captured.
  checkSrdmSettings(options.size, srdm);
  if (builder == SrdmBuilder::kGpu) {
    if (srdm.simplifier != SrdmSimplifier::kGreedy)
      throwInput(
          "--srdm-builder gpu with --srdm-simplify {}: the GPU builder runs only the "
          "greedy simplifier (allowed: --srdm-simplify greedy, or --srdm-builder cpu)",
          srdmSimplifierName(srdm.simplifier));
    gpu_builder_ = std::make_unique<SrdmGpuBuilder>();
  }
}

void DepthMapCapture::allocate(int maps) {
  const int count = std::max(maps, 1);
  if (colors_.layers() == count) return;
  GLint max_layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (count * srdm_settings_.domains > max_layers)
    throwGpu(
        "--srdm-n {} with {} depth maps needs {} texture layers, beyond the driver's "
        "GL_MAX_ARRAY_TEXTURE_LAYERS ({}: --srdm-n up to {} would fit)",
        srdm_settings_.domains, count, count * srdm_settings_.domains, max_layers,
        max_layers / count);
  const int w = options_.size;
  colors_ = gpu::Texture::create2DArray(GL_RGBA16F, w, w, count, gpu::Texture::fullMipLevels(w));
  depths_ = gpu::Texture::create2DArray(GL_DEPTH_COMPONENT32F, w, w, count, 1);
  const int pairs = (srdm_settings_.points + 1) / 2;
  srdms_ = gpu::Texture::create2DArray(GL_RGBA32F, pairs, w, count * srdm_settings_.domains, 1);
  color_keys_.assign(size_t(count), ColorKey{});
  color_valid_.assign(size_t(count), false);
  depth_valid_.assign(size_t(count), false);
  built_for_.assign(size_t(count), DepthMapSpec{});
  built_shape_.assign(size_t(count), 0);
  dropped_.assign(size_t(count), 0);
}

int DepthMapCapture::update(GpuScene& gpu, ScenePasses& passes,
                            const std::vector<DepthMapSpec>& specs, const FrameSettings& settings,
                            const RecapturePolicy& policy) {
  allocate(int(specs.size()));
  const Light& light = gpu.light();
  std::vector<ColorKey> keys(specs.size());
  std::vector<bool> depth_ok(specs.size());
  std::vector<Drift> drift(specs.size());
  for (size_t i = 0; i < specs.size(); ++i) {
    const DepthMapSpec& spec = specs[i];
    const mat4& model = gpu.instanceMatrix(spec.instance);
    // The light as the object sees it: a translation changes nothing, a rotation may.
    const vec3 local_light = glm::normalize(glm::inverse(mat3(model)) * light.direction);
    // A normal map depends on nothing the key holds.
    keys[i] = spec.reflector ? ColorKey{} : ColorKey{local_light, light.color, light.ambient};
    // A deforming object's maps are redrawn when its shape changes (a rigid motion moves their
    // cameras with it and redraws nothing): the depth must match, whatever the budget.
    depth_ok[i] = depth_valid_[i] && sameSpec(built_for_[i], spec) &&
                  built_shape_[i] == gpu.shapeVersion(spec.instance);
    drift[i].invalid = !depth_ok[i] || !color_valid_[i];
    // The colour is re-shaded once the light, as the object sees it, turned beyond the
    // tolerance (a change of its colour is beyond every tolerance).
    const ColorKey& old = color_keys_[i];
    if (old.light_dir != keys[i].light_dir)
      drift[i].angle =
          std::acos(std::clamp(glm::dot(old.light_dir, keys[i].light_dir), -1.0f, 1.0f));
    drift[i].unmeasured = old.light_color != keys[i].light_color || old.ambient != keys[i].ambient;
  }
  const std::vector<int> due = chooseRecaptures(drift, policy);
  pending_ = int(chooseRecaptures(drift, {policy.angle_degrees, policy.texels, 0}).size()) -
             int(due.size());
  for (int k : due) {
    const size_t i = size_t(k);
    render(gpu, passes, specs[i], k, !depth_ok[i], settings);
    color_keys_[i] = keys[i];
    color_valid_[i] = true;
    if (!depth_ok[i]) {
      build(k, depthMapView(specs[i], gpu.instanceMatrix(specs[i].instance), options_));
      built_for_[i] = specs[i];
      built_shape_[i] = gpu.shapeVersion(specs[i].instance);
      depth_valid_[i] = true;
    }
  }
  // The re-shaded layers' mip chains: all at once when most are new.
  if (due.size() * 2 > size_t(colors_.layers()))
    colors_.generateMipmaps();
  else
    for (int k : due) colors_.generateMipmaps(k, 1);
  color_captures_ += long(due.size());
  return int(due.size());
}

void DepthMapCapture::render(GpuScene& gpu, ScenePasses& passes, const DepthMapSpec& spec,
                             int layer, bool with_depth, const FrameSettings& settings) {
  // A colour-only capture renders against a scratch depth buffer, leaving the depth map (and
  // the SRDMs built from it) as they are.
  fbo_.attachColor(0, colors_, 0, layer);
  if (with_depth)
    fbo_.attachDepth(depths_, 0, layer);
  else
    fbo_.attachDepth(scratch_depth_);
  fbo_.setDrawBuffers(1);
  fbo_.checkComplete("depth-map capture");
  fbo_.bind();
  glViewport(0, 0, options_.size, options_.size);
  const float clear[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, clear);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far_depth);
  passes.begin(depthMapView(spec, gpu.instanceMatrix(spec.instance), options_), settings);
  (spec.reflector ? normal_program_ : program_).use();
  gpu.draw(spec.instance);
  for (int member : spec.members) gpu.draw(member);
  if (with_depth) ++depth_captures_;
}

void DepthMapCapture::build(int layer, const View& view) {
  Stopwatch watch;
  const int n = srdm_settings_.domains;
  if (gpu_builder_) {
    // The map's depth layer as a 2D texture and its n SRDM layers as an array: the builder
    // reads and writes them in place, with no read-back.
    const gpu::Texture depth = gpu::Texture::view(depths_, GL_TEXTURE_2D, layer, 1);
    gpu::Texture out = gpu::Texture::view(srdms_, GL_TEXTURE_2D_ARRAY, layer * n, n);
    gpu_builder_->build(depth, view.nearPlane(), view.farPlane(), srdm_settings_, out);
    dropped_[size_t(layer)] = gpu_builder_->droppedSamples();  // waits for the build
  } else {
    DepthMap map;
    map.size = options_.size;
    map.near = view.nearPlane();
    map.far = view.farPlane();
    map.depth.resize(size_t(map.size) * size_t(map.size));
    depths_.downloadLayer(0, layer, GL_DEPTH_COMPONENT, GL_FLOAT, map.depth.data(),
                          map.depth.size() * sizeof(float));
    const Srdm srdm = buildSrdm(map, srdm_settings_);
    srdms_.uploadLayers(0, layer * n, n, GL_RGBA, GL_FLOAT, srdm.texels.data());
    dropped_[size_t(layer)] = srdm.dropped_samples;
  }
  last_build_ms_ = watch.ms();
  ++srdm_builds_;
}

int DepthMapCapture::droppedSamples() const {
  int dropped = 0;
  for (int d : dropped_) dropped += d;
  return dropped;
}

}  // namespace mirage
