#include "support/render_pair.h"

#include "core/display.h"
#include "eval/metrics.h"
#include "raytrace/tracer.h"

namespace mirage::test {

RenderPair renderWithTruth(const Scene& scene, const std::string& method, ivec2 size,
                           const FrameSettings& settings,
                           const std::map<std::string, std::string>& params, float time) {
  FrameRenderer renderer(scene, size);
  View view(scene.camera(), size);
  auto m = renderer.createMethod(method, params, settings);
  renderer.render(*m, view, time, settings);
  RenderedFrame frame = renderer.read();
  RayTracer tracer(scene, renderer.environment());
  tracer.prepare(time);
  TraceResult truth = tracer.render(view, {settings.order, 1});
  return {displayed(frame.color), displayed(truth.color), frame.ids, truth.ids};
}

double reflectorPsnr(const RenderPair& p) {
  return psnrFromMse(meanSquaredError(p.gpu, p.cpu, &p.cpu_ids));
}

Image displayed(const Image& linear) {
  return toDisplay(linear, DisplaySettings{1.0f, ToneMap::kAces});
}

}  // namespace mirage::test
