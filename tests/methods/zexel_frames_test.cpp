// Method `zexel` frame by frame: the GPU and the CPU warpers agree, two maps expose less than
// one, the no-clear option keeps the last frame in exposures, magnification-sized splats close
// what 1x1 splats leave open, and the hierarchy warps fewer zexels at little cost.
#include <gtest/gtest.h>

#include "eval/metrics.h"
#include "methods/frame.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/render_pair.h"

namespace mirage::test {
namespace {

using Params = std::map<std::string, std::string>;

struct ZexelFrame {
  RenderedFrame frame;
  std::map<std::string, double> stats;
};

// Renders `views` in sequence with one zexel method (its state carried from frame to frame) and
// returns the last frame.
ZexelFrame renderZexel(const Scene& scene, const Params& params, const std::vector<View>& views) {
  FrameSettings settings;
  settings.order = 1;
  FrameRenderer renderer(scene, views.front().size());
  auto method = renderer.createMethod("zexel", params, settings);
  for (const View& v : views) renderer.render(*method, v, 0.0f, settings);
  return {renderer.read(), method->stats()};
}

// The mirror-room camera moved sideways by `dx`.
View movedView(const Scene& scene, ivec2 size, float dx) {
  CameraDesc c = scene.camera();
  c.position.x += dx;
  c.target.x += dx;
  return View(c, size);
}

// Pixels of the mirror (reflector ids) that are pure black: exposures nothing filled.
size_t blackMirrorPixels(const RenderedFrame& f) {
  size_t black = 0;
  for (int y = 0; y < f.color.height(); ++y)
    for (int x = 0; x < f.color.width(); ++x)
      if (f.ids(x, y) != 0 && vec3(f.color(x, y)) == vec3(0.0f)) ++black;
  return black;
}

class ZexelFrames : public GlTest {
 protected:
  Scene scene_ = makeBuiltinScene("mirror-room");
  ivec2 size_{320, 240};
  View view() const { return View(scene_.camera(), size_); }
};

// Both warpers run one algorithm on one shared code (tiles, McMillan's warp, cells) and the
// mirror's shader blends what either left: the frames agree but for float rounding between the
// compute shader and the C++ code, and ties the GPU breaks either way (measured: no pixel
// differs).
TEST_F(ZexelFrames, GpuAndCpuWarpersAgree) {
  for (const char* splat : {"1", "3", "0"}) {
    auto params = [&](const char* warper) {
      return Params{{"zexel-splat", splat}, {"zexel-fill", "0"}, {"zexel-warper", warper}};
    };
    const ZexelFrame g = renderZexel(scene_, params("gpu"), {view()});
    const ZexelFrame c = renderZexel(scene_, params("cpu"), {view()});
    EXPECT_EQ(g.stats.at("zexels_warped"), c.stats.at("zexels_warped"));
    EXPECT_EQ(g.stats.at("exposed_fraction"), c.stats.at("exposed_fraction")) << splat;
    size_t differ = 0, mirror = 0;
    for (int y = 0; y < g.frame.color.height(); ++y)
      for (int x = 0; x < g.frame.color.width(); ++x) {
        if (g.frame.ids(x, y) == 0) continue;
        ++mirror;
        differ += glm::length(vec3(g.frame.color(x, y)) - vec3(c.frame.color(x, y))) > 1e-3f;
      }
    std::printf("splat %s: %zu of %zu mirror pixels differ between the warpers; exposed %.4f\n",
                splat, differ, mirror, g.stats.at("exposed_fraction"));
    EXPECT_GT(mirror, 1000u);
    EXPECT_LE(differ, mirror / 1000) << splat;
  }
}

// The mirror's pixels are resolved by the compute pass or by the mirror's own shader, the same
// shared gather either way: the frames are equal to the bit (defaults, magnification splats,
// 2 x 2 splats, the no-clear option over two frames) on mirror-room and two-mirrors. Choosing by
// itself (auto, from the second frame: the first has no count of a mirror's pixels), the method
// takes the pass for the mirror in front of the eye, whose screen rectangle is about the mirror
// (1.6 times its visible pixels on two-mirrors), and not for two-mirrors' mirror behind the eye,
// whose bounds project to the whole screen and which shows no pixel.
TEST_F(ZexelFrames, ResolvePassAndMirrorShaderGiveTheSameFrame) {
  for (const char* name : {"mirror-room", "two-mirrors"}) {
    const Scene scene = makeBuiltinScene(name);
    const View v(scene.camera(), size_);
    for (const Params& p : {Params{}, Params{{"zexel-splat", "0"}}, Params{{"zexel-splat", "2"}},
                            Params{{"zexel-clear", "off"}}}) {
      auto with = [&](const char* where) {
        Params q = p;
        q["zexel-resolve"] = where;
        return renderZexel(scene, q, {v, v});
      };
      const ZexelFrame pass = with("pass"), mirror = with("mirror");
      EXPECT_GT(pass.stats.at("zexel_resolve_passes"), 0.0);
      EXPECT_EQ(mirror.stats.at("zexel_resolve_passes"), 0.0);
      size_t differ = 0;
      for (int y = 0; y < pass.frame.color.height(); ++y)
        for (int x = 0; x < pass.frame.color.width(); ++x)
          differ += pass.frame.color(x, y) != mirror.frame.color(x, y) ? 1 : 0;
      EXPECT_EQ(differ, 0u) << name << ", " << (p.empty() ? "defaults" : p.begin()->first);
    }
    const ZexelFrame chosen = renderZexel(scene, {}, {v, v});
    EXPECT_EQ(chosen.stats.at("zexel_resolve_passes"), 1.0) << name;
    const ZexelFrame all = renderZexel(scene, {{"zexel-resolve", "pass"}}, {v, v});
    EXPECT_EQ(all.stats.at("zexel_resolve_passes"), std::string(name) == "mirror-room" ? 1.0 : 2.0)
        << name;
  }
}

TEST_F(ZexelFrames, TwoMapsExposeLessThanOne) {
  auto maps = [](const char* per_frame) {
    return Params{{"zexel-maps", "8"}, {"zexel-maps-per-frame", per_frame}, {"zexel-fill", "0"}};
  };
  const Params one = maps("1"), two = maps("2");
  const double e1 = renderZexel(scene_, one, {view()}).stats.at("exposed_fraction");
  const double e2 = renderZexel(scene_, two, {view()}).stats.at("exposed_fraction");
  std::printf("exposed mirror pixels: one map %.4f, two maps %.4f\n", e1, e2);
  EXPECT_GT(e1, 0.0);
  EXPECT_LT(e2, 0.8 * e1);
}

// A 96² map is magnified about three times on the mirror: 1x1 splats leave cracks between its
// zexels, splats sized by the warp's magnification close them (disocclusions stay open).
TEST_F(ZexelFrames, MagnificationSplatsCloseWhatSmallSplatsLeaveOpen) {
  const double small =
      renderZexel(scene_, {{"zexel-splat", "1"}, {"zexel-size", "96"}, {"zexel-fill", "0"}},
                  {view()})
          .stats.at("exposed_fraction");
  const double sized =
      renderZexel(scene_, {{"zexel-splat", "0"}, {"zexel-size", "96"}, {"zexel-fill", "0"}},
                  {view()})
          .stats.at("exposed_fraction");
  std::printf("exposed mirror pixels: 1x1 splats %.4f, magnification-sized %.4f\n", small, sized);
  EXPECT_LT(sized, 0.5 * small);
}

// Walking sideways, pixels exposed now were covered a frame ago: kept, they are not black.
TEST_F(ZexelFrames, NoClearKeepsTheLastFrameInExposures) {
  std::vector<View> walk;
  for (int i = 0; i < 4; ++i) walk.push_back(movedView(scene_, size_, 0.15f * float(i)));
  const Params base = {{"zexel-fill", "0"}, {"zexel-splat", "1"}};
  const Params keep = {{"zexel-fill", "0"}, {"zexel-splat", "1"}, {"zexel-clear", "off"}};
  const ZexelFrame cleared = renderZexel(scene_, base, walk);
  const ZexelFrame kept = renderZexel(scene_, keep, walk);
  const size_t black_cleared = blackMirrorPixels(cleared.frame);
  const size_t black_kept = blackMirrorPixels(kept.frame);
  std::printf("black mirror pixels after a walk: cleared %zu, kept %zu\n", black_cleared,
              black_kept);
  EXPECT_GT(black_cleared, 100u);
  EXPECT_LT(black_kept, black_cleared / 2);
}

TEST_F(ZexelFrames, HierarchyWarpsFewerZexelsAtLittleCost) {
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{640, 480};
  RenderPair full = renderWithTruth(scene_, "zexel", size, settings, {{"zexel-lod", "off"}});
  RenderPair lod = renderWithTruth(scene_, "zexel", size, settings, {{"zexel-lod", "on"}});
  std::printf(
      "reflector PSNR: full maps %.2f dB (%.0f zexels), hierarchy %.2f dB (mean level %.2f, "
      "%.0f zexels)\n",
      reflectorPsnr(full), full.stats.at("zexels_warped"), reflectorPsnr(lod),
      lod.stats.at("zexel_level"), lod.stats.at("zexels_warped"));
  EXPECT_GT(lod.stats.at("zexel_level"), 0.0);
  EXPECT_LT(lod.stats.at("zexels_warped"), 0.8 * full.stats.at("zexels_warped"));
  EXPECT_GT(reflectorPsnr(lod), reflectorPsnr(full) - 1.0);
}

}  // namespace
}  // namespace mirage::test
