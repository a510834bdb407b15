#include "support/render_pair.h"

#include "core/display.h"
#include "raytrace/tracer.h"

namespace mirage::test {

RenderPair renderWithTruth(const Scene& scene, const std::string& method, ivec2 size,
                           const FrameSettings& settings,
                           const std::map<std::string, std::string>& params) {
  FrameRenderer renderer(scene, size);
  View view(scene.camera(), size);
  auto m = renderer.createMethod(method, params, settings);
  renderer.render(*m, view, 0.0f, settings);
  RenderedFrame frame = renderer.read();
  RayTracer tracer(scene, renderer.environment());
  tracer.prepare(0.0f);
  TraceResult truth = tracer.render(view, {settings.order, 1});
  DisplaySettings display{1.0f, ToneMap::kAces};
  return {toDisplay(frame.color, display), toDisplay(truth.color, display), frame.ids, truth.ids};
}

}  // namespace mirage::test
