#include "methods/planar/planar_probes.h"

#include <algorithm>

#include "shading/gpu_types.h"

namespace mirage {

PlanarProbes::PlanarProbes(const Scene& scene, const std::vector<int>& planar, int size,
                           const RecapturePolicy& recapture)
    : diffuse_(scene.diffuseInstances()),
      probes_(size),
      recapture_(recapture),
      program_(
          gpu::Program::graphics("render/shaders/scene.vert", "methods/planar/planar_probe.frag")) {
  for (int i : scene.reflectorInstances())
    if (std::find(planar.begin(), planar.end(), i) == planar.end()) curved_.push_back(i);
}

void PlanarProbes::update(FrameContext& frame, const gpu::Program& base_program) {
  const Scene& scene = frame.gpu.scene();
  const std::vector<int> reflectors = scene.reflectorInstances();
  const float radius = std::max(scene.bounds(frame.gpu.time()).radius(), 1e-3f);
  probes_.updateAtReflectors(frame.gpu, frame.settings.mip, curved_, diffuse_, reflectors,
                             recapture_, radius, [&](int k, const View& v) {
                               frame.passes.begin(v, frame.settings);
                               frame.passes.drawDirect();
                               frame.passes.drawReflectors(base_program, curved_[size_t(k)]);
                             });
}

void PlanarProbes::draw(const FrameContext& frame) const {
  probes_.bind(MIRAGE_UNIT_METHOD);
  for (size_t k = 0; k < curved_.size(); ++k) {
    program_.set("u_layer", int(k));
    frame.passes.drawReflectorInstances(program_, std::span<const int>(&curved_[k], 1));
  }
}

}  // namespace mirage
