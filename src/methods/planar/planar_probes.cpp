#include "methods/planar/planar_probes.h"

#include <algorithm>

#include "shading/gpu_types.h"

namespace mirage {

PlanarProbes::PlanarProbes(const Scene& scene, const std::vector<int>& planar, int size)
    : diffuse_(scene.diffuseInstances()),
      size_(size),
      reflectors_(scene.reflectorInstances().size()),
      program_(
          gpu::Program::graphics("render/shaders/scene.vert", "methods/planar/planar_probe.frag")) {
  for (int i : scene.reflectorInstances())
    if (std::find(planar.begin(), planar.end(), i) == planar.end()) curved_.push_back(i);
}

void PlanarProbes::update(FrameContext& frame, const gpu::Program& base_program) {
  std::vector<uint64_t> key = frame.gpu.probeKey(diffuse_);
  const bool mip = frame.settings.mip;
  if (captured_ && key == key_ && mip == mip_) return;
  const int levels = mip ? gpu::Texture::fullMipLevels(size_) : 1;
  if (probes_.levels() != levels || probes_.layers() != 6 * int(reflectors_))
    probes_ = gpu::Texture::createCubeArray(GL_RGBA16F, size_, int(reflectors_), levels);
  if (!cube_) cube_ = std::make_unique<CubeCapture>(size_);
  const Scene& scene = frame.gpu.scene();
  const std::vector<int> reflectors = scene.reflectorInstances();
  const float radius = std::max(scene.bounds(frame.gpu.time()).radius(), 1e-3f);
  for (int instance : curved_) {
    const int layer =
        int(std::find(reflectors.begin(), reflectors.end(), instance) - reflectors.begin());
    const vec3 centre = frame.gpu.instanceBounds(instance).center();
    cube_->capture(probes_, layer, centre, 1e-3f * radius, 100.0f * radius, [&](const View& v) {
      frame.passes.begin(v, frame.settings);
      frame.passes.drawDirect();
      frame.passes.drawReflectors(base_program, instance);
    });
    ++captures_;
  }
  if (mip) probes_.generateMipmaps();
  captured_ = true;
  key_ = std::move(key);
  mip_ = mip;
}

void PlanarProbes::draw(const FrameContext& frame) const {
  probes_.bind(MIRAGE_UNIT_METHOD);
  frame.passes.drawReflectorInstances(program_, curved_);
}

}  // namespace mirage
