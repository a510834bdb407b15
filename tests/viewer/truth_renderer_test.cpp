// The viewer's background reference: it refines through its levels to the ray tracer's own frame
// at the last one (the same pixels as a render on this thread), starts over when the view
// changes, and the PSNR it feeds the panel is the metrics' over the reference's reflector
// pixels, the frame box-filtered first.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "core/display.h"
#include "eval/metrics.h"
#include "raytrace/tracer.h"
#include "scene/builtin_scenes.h"
#include "viewer/truth_renderer.h"
#include "viewer/viewer_output.h"

namespace mirage::test {
namespace {

// Waits (at most 60 s) until the renderer has published level `level` of `request`.
bool waitFor(TruthRenderer& truth, const TruthRequest& request, int level, TruthImage& out) {
  for (int i = 0; i < 30000; ++i) {
    truth.takeNewer(out);
    if (out.request == request && out.level == level) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

TEST(TruthRenderer, RefinesToTheRayTracersFrameAndStartsOverWhenTheViewChanges) {
  const Scene scene = makeBuiltinScene("sphere-over-checker");
  const EnvironmentMap env = EnvironmentMap::forScene(scene);
  TruthRenderer truth(scene, env, 2);
  TruthRequest request;
  request.camera = scene.camera();
  request.size = {160, 120};
  request.divisor = 2;
  request.order = 2;
  EXPECT_EQ(request.levelSize(0), ivec2(20, 15));
  EXPECT_EQ(request.levelSize(1), ivec2(40, 30));
  EXPECT_EQ(request.levelSize(2), ivec2(80, 60));
  EXPECT_EQ(request.levelSize(3), ivec2(80, 60));
  truth.request(request);
  TruthImage image;
  ASSERT_TRUE(waitFor(truth, request, TruthRequest::kLevels - 1, image));
  EXPECT_EQ(image.color.width(), 80);
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  const TraceResult direct = tracer.render(View(request.camera, {80, 60}), {2, 4});
  EXPECT_EQ(image.color.data()[1234], direct.color.data()[1234]);
  EXPECT_TRUE(std::isinf(psnrFromMse(meanSquaredError(image.color, direct.color))));
  EXPECT_EQ(image.ids.data()[4321], direct.ids.data()[4321]);
  // The same request again keeps what it has: nothing new arrives.
  truth.request(request);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  TruthImage copy = image;
  EXPECT_FALSE(truth.takeNewer(copy));
  // A new view starts from its first level.
  TruthRequest moved = request;
  moved.camera.position.x += 0.5f;
  truth.request(moved);
  ASSERT_TRUE(waitFor(truth, moved, TruthRequest::kLevels - 1, image));
  EXPECT_GT(image.serial, copy.serial);
  truth.cancel();
  EXPECT_TRUE(truth.failure().empty());
}

TEST(TruthPsnr, IsTheMetricOverReflectorPixelsOfTheBoxFilteredFrame) {
  // A 4x2 frame against a 2x1 reference: each reference pixel is the mean of a 2x2 block.
  RenderedFrame frame{Image(4, 2), IdImage(4, 2)};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) frame.color(x, y) = vec4(x < 2 ? 0.2f : 0.6f, 0.1f, 0.3f, 1.0f);
  TruthImage truth;
  truth.color = Image(2, 1);
  truth.ids = IdImage(2, 1);
  truth.color(0, 0) = vec4(0.2f, 0.1f, 0.3f, 1.0f);  // equal to the left block's mean
  truth.color(1, 0) = vec4(0.1f, 0.1f, 0.3f, 1.0f);  // differs from the right block's
  truth.ids(0, 0) = 1;
  const DisplaySettings display;
  EXPECT_TRUE(std::isinf(truthPsnr(frame, truth, display)));  // only the left pixel counts
  truth.ids(1, 0) = 1;
  // Both pixels count: the right block's mean, red 0.6, against the reference's 0.1, and only
  // in red. Through the clamp tone map and the sRGB curve (IEC 61966-2-1: 1.055 c^(1/2.4) -
  // 0.055 above 0.0031308) the squared difference of that channel over 2 pixels x 3 channels.
  DisplaySettings clamp;
  clamp.tonemap = ToneMap::kClamp;
  auto srgb = [](double c) { return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; };
  const double diff = srgb(0.6) - srgb(0.1);
  EXPECT_NEAR(truthPsnr(frame, truth, clamp), 10.0 * std::log10(6.0 / (diff * diff)), 1e-4);
  truth.ids = IdImage(2, 1);  // no reflector: no figure
  EXPECT_TRUE(std::isnan(truthPsnr(frame, truth, display)));
}

}  // namespace
}  // namespace mirage::test
