#include "support/render_pair.h"

#include "core/display.h"
#include "eval/metrics.h"
#include "raytrace/tracer.h"

namespace mirage::test {

RenderPair renderWithTruth(const Scene& scene, const std::string& method, ivec2 size,
                           const FrameSettings& settings,
                           const std::map<std::string, std::string>& params, float time, int ssaa) {
  const ivec2 frame_size = size * ssaa;
  FrameSettings scaled = settings;
  scaled.pixel_scale = ssaa;
  FrameRenderer renderer(scene, frame_size);
  View view(scene.camera(), frame_size);
  auto m = renderer.createMethod(method, params, scaled);
  renderer.render(*m, view, time, scaled);
  RenderedFrame frame = downsample(renderer.read(), ssaa);
  RayTracer tracer(scene, renderer.environment());
  tracer.prepare(time);
  TraceResult t = tracer.render(view, {settings.order, 1});
  RenderedFrame truth = downsample({std::move(t.color), std::move(t.ids)}, ssaa);
  return {displayed(frame.color), displayed(truth.color), frame.ids, truth.ids, m->stats()};
}

double reflectorPsnr(const RenderPair& p) {
  return psnrFromMse(meanSquaredError(p.gpu, p.cpu, &p.cpu_ids));
}

Image displayed(const Image& linear) {
  return toDisplay(linear, DisplaySettings{1.0f, ToneMap::kAces});
}

}  // namespace mirage::test
