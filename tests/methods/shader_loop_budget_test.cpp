// The worst cases of the shaders that loop over data, in the loop limiter's count
// (gpu/loop_budget.h): each formula against a hand count of its loops, the defaults and the
// README's sizes within the budget, and a setting beyond it refused as a driver limit (the
// method falls back, saying which settings), never a frame whose loops were cut short.
#include <gtest/gtest.h>

#include <string>

#include "gpu/loop_budget.h"
#include "methods/depthmap/depthmap_loop_cost.h"
#include "methods/frame.h"
#include "methods/hybrid/splat_pass.h"
#include "methods/impostor/billboard_stage.h"
#include "methods/zexel/zexel_cube_map.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

using gpu::kShaderLoopBudget;

TEST(ShaderLoopCosts, AreTheLoopsCountedByHand) {
  // Two bounces over ten entries: 2 x (1 + 11) + 1.
  EXPECT_EQ(impostorTraceLoopCost(2, 10, 0), 25);
  EXPECT_EQ(impostorTraceLoopCost(1, 0, 5), 8);
  // A map search: the clip's 6 planes (7), an SRDM row of 4 point pairs of 2 points (17).
  EXPECT_EQ(mapSearchLoopCost(MIRAGE_DEPTHMAP_SEARCH_SRDM, 8, 256), 7 + 17);
  EXPECT_EQ(mapSearchLoopCost(MIRAGE_DEPTHMAP_SEARCH_LINEAR, 8, 256), 7 + 258);
  EXPECT_EQ(mapSearchLoopCost(MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE, 8, 256), 7 + 3 * 17 + 18);
  // One object, one map tried once: the next-map scan (2) and the search (24), in a loop of 1.
  EXPECT_EQ(depthMapHookLoopCost(1, 1, 2, 0, 24), 1 * (1 + 1 * (1 + 2 + 24) + 1) + 1);
  // Self maps add their searches to each entry (both sides of the branch run).
  EXPECT_EQ(depthMapHookLoopCost(1, 1, 1, 2, 24), 1 * (1 + 28 + 2 * 25 + 1) + 1);
  // A point of the splatting pass at 8-pixel splats: the hull (9), the cubic's pieces
  // (3 x 42 + 1), three splats of 64 pixels (3 x 66 + 1).
  SplatSettings splat;
  splat.pixel_scale = 1;
  EXPECT_EQ(SplatPass::pointCost(splat), 9 + 127 + 199);
  splat.first_only = true;
  EXPECT_EQ(SplatPass::pointCost(splat), 9 + 127 + 67);
}

TEST(ShaderLoopCosts, TheDefaultsAndTheReadmesSizesFit) {
  // billboard, order 2, lists of every object of plaza (240) and its 20 reflectors.
  EXPECT_LE(impostorTraceLoopCost(2, 260, 0), kShaderLoopBudget);
  // depthmap's defaults: SRDM rows of 8 points, a map tried twice, 34 groups in a list (the
  // most the driver's 2,048 layers hold at 60 SRDM domains).
  const long long search = mapSearchLoopCost(MIRAGE_DEPTHMAP_SEARCH_SRDM, 8, 256);
  EXPECT_LE(impostorTraceLoopCost(2, 40, depthMapHookLoopCost(34, 1, 2, 0, search)),
            kShaderLoopBudget);
  // zexel's curved search at its defaults (256-texel faces, steps of a texel).
  EXPECT_LE(zexelInverseLoopCost(zexelInverseSettings(256, 1.0f)), kShaderLoopBudget);
  // The splatting pass under --ssaa 8 still fits a step of points in a run.
  SplatSettings splat;
  splat.pixel_scale = 8;
  EXPECT_LE(3 + 1 + SplatPass::pointCost(splat), kShaderLoopBudget);
}

class ShaderLoopBudget : public GlTest {};

// An impostor trace whose worst case is beyond the budget is a driver limit: depthmap falls back
// to envmap with the settings that make it.
TEST_F(ShaderLoopBudget, ATraceBeyondItFallsBackNamingTheSettings) {
  expectFallback();
  const Scene scene = makeBuiltinScene("teapot-sphere");
  FrameRenderer renderer(scene, {96, 64});
  FrameSettings settings;
  settings.order = 16;
  auto m = renderer.createMethod(
      "depthmap", {{"srdm-m", "256"}, {"depthmap-maps", "6"}, {"depthmap-tries", "6"}}, settings);
  renderer.render(*m, View(scene.camera(), {96, 64}), 0.0f, settings);
  const std::string why = m->fallbackReason();
  EXPECT_NE(why.find("the impostor trace (--order 16"), std::string::npos) << why;
  EXPECT_NE(why.find("--srdm-m 256"), std::string::npos) << why;
  // At order 2 the same settings fit and draw.
  settings.order = 2;
  auto fits = renderer.createMethod(
      "depthmap", {{"srdm-m", "256"}, {"depthmap-maps", "6"}, {"depthmap-tries", "6"}}, settings);
  renderer.render(*fits, View(scene.camera(), {96, 64}), 0.0f, settings);
  EXPECT_EQ(fits->fallbackReason(), "");
}

TEST_F(ShaderLoopBudget, ZexelsCurvedSearchBeyondItFallsBack) {
  expectFallback();
  EXPECT_GT(zexelInverseLoopCost(zexelInverseSettings(2048, 0.25f)), kShaderLoopBudget);
  const Scene scene = makeBuiltinScene("teapot-sphere");
  FrameRenderer renderer(scene, {64, 48});
  FrameSettings settings;
  settings.order = 1;
  auto m = renderer.createMethod(
      "zexel", {{"zexel-cube-size", "2048"}, {"zexel-curved-step", "0.25"}}, settings);
  EXPECT_NE(m->fallbackReason().find("zexel's curved search (--zexel-cube-size 2048"),
            std::string::npos)
      << m->fallbackReason();
}

}  // namespace
}  // namespace mirage::test
