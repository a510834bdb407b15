// Captures in a playing scene, amortised (render/recapture.h): with both tolerances 0 and no
// budget every method's frame along a played path is what a fresh method draws at that time;
// with the defaults each frame re-captures at most the budget, the frame stays close to the
// exact one, and a scene that stops lets the captures the budget left behind catch up.
#include <gtest/gtest.h>

#include "methods/frame.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class Recapture : public GlTest {};

using Params = std::map<std::string, std::string>;
using Counts = std::map<std::string, double>;

const Params kExact = {{"recapture-angle", "0"},
                       {"recapture-texels", "0"},
                       {"billboard-budget", "0"},
                       {"probe-budget", "0"}};

constexpr ivec2 kSize{128, 96};

// spheres9 with four bobbing mirror spheres: they reflect one another and the objects.
Scene fourBobbingSpheres() {
  SceneOptions options;
  options.reflectors = 4;
  return makeBuiltinScene("spheres9", options);
}

// The frame of a method that has played `times` (0.1 s apart from 0), at the last of them.
RenderedFrame played(FrameRenderer& renderer, const std::string& method, const Params& params,
                     int frames, std::vector<Counts>* counts = nullptr) {
  FrameSettings settings;
  auto m = renderer.createMethod(method, params, settings);
  const View view(renderer.scene().camera(), kSize);
  for (int f = 0; f < frames; ++f) {
    Counts c;
    renderer.render(*m, view, 0.1f * float(f), settings, nullptr, &c);
    if (counts) counts->push_back(c);
  }
  return renderer.read();
}

RenderedFrame fresh(FrameRenderer& renderer, const std::string& method, float time) {
  FrameSettings settings;
  auto m = renderer.createMethod(method, kExact, settings);
  renderer.render(*m, View(renderer.scene().camera(), kSize), time, settings);
  return renderer.read();
}

// Each method's counter of the captures it makes in a moving scene.
const std::map<std::string, std::string> kCaptureCounter = {{"billboard", "billboard_captures"},
                                                            {"depthmap", "billboard_captures"},
                                                            {"envmap", "cube_captures"},
                                                            {"envmap-box", "cube_captures"},
                                                            {"hybrid", "background_captures"},
                                                            {"zexel", "zexel_cube_captures"},
                                                            {"ssr", "cube_captures"}};

TEST_F(Recapture, ExactPolicyAlongAPlayedPathIsAFreshCaptureAtEveryTime) {
  const Scene scene = fourBobbingSpheres();
  FrameRenderer renderer(scene, kSize);
  for (const auto& [method, counter] : kCaptureCounter) {
    SCOPED_TRACE(method);
    const RenderedFrame a = played(renderer, method, kExact, 6);
    const RenderedFrame b = fresh(renderer, method, 0.5f);
    // The mip chains of the few layers a frame re-captures are built by blits rather than by
    // glGenerateTextureMipmap: both are 2:1 box filters, to the bit.
    EXPECT_TRUE(imagesEqual(a.color, b.color, 0.0f, &b.ids, method + "-exact"));
  }
}

// Never re-captured after the first frame: what amortising must beat.
const Params kFrozen = {{"recapture-angle", "90"}, {"recapture-texels", "10000"}};

double reflectorPsnr(const RenderedFrame& a, const RenderedFrame& exact) {
  return psnrFromMse(meanSquaredError(a.color, exact.color, &exact.ids));
}

TEST_F(Recapture, DefaultsStayWithinTheBudgetAndBeatFrozenCaptures) {
  const Scene scene = fourBobbingSpheres();
  FrameRenderer renderer(scene, kSize);
  const std::map<std::string, int> budget = {{"billboard", 16}, {"envmap", 1}, {"zexel", 1}};
  for (const auto& [method, per_frame] : budget) {
    SCOPED_TRACE(method);
    std::vector<Counts> counts;
    const RenderedFrame a = played(renderer, method, {}, 8, &counts);
    const std::string counter = kCaptureCounter.at(method);
    EXPECT_GT(counts[0][counter], double(per_frame)) << "the first frame captures everything";
    for (size_t f = 1; f < counts.size(); ++f) EXPECT_LE(counts[f][counter], double(per_frame));
    const RenderedFrame frozen = played(renderer, method, kFrozen, 8);
    const RenderedFrame exact = fresh(renderer, method, 0.7f);
    const double amortised_db = reflectorPsnr(a, exact), frozen_db = reflectorPsnr(frozen, exact);
    // The spheres bob by up to 0.5 in 2 s: 0.7 s leaves frozen captures far off.
    EXPECT_GT(amortised_db, frozen_db + 1.0)
        << "amortised " << amortised_db << " dB, frozen " << frozen_db << " dB against exact";
  }
}

TEST_F(Recapture, AStoppedSceneCatchesUpOnWhatTheBudgetLeft) {
  const Scene scene = fourBobbingSpheres();
  FrameRenderer renderer(scene, kSize);
  FrameSettings settings;
  auto m = renderer.createMethod("billboard", {{"billboard-budget", "2"}}, settings);
  const View view(scene.camera(), kSize);
  renderer.render(*m, view, 0.0f, settings);
  renderer.render(*m, view, 0.4f, settings);
  const RenderedFrame behind = renderer.read();
  const double pending = m->stats().at("billboards_pending");
  ASSERT_GT(pending, 2.0) << "a 0.4 s step moves more billboards than a budget of 2";
  for (int f = 0; f < int(pending / 2.0) + 1; ++f) renderer.render(*m, view, 0.4f, settings);
  EXPECT_EQ(m->stats().at("billboards_pending"), 0.0);
  const RenderedFrame caught_up = renderer.read();
  const RenderedFrame exact = fresh(renderer, "billboard", 0.4f);
  // What is left is within the tolerances (1 degree, 2 texels).
  EXPECT_GT(reflectorPsnr(caught_up, exact), reflectorPsnr(behind, exact) + 3.0);
  EXPECT_TRUE(psnrAtLeast(caught_up.color, exact.color, floors::kRecaptureCaughtUp, &exact.ids));
}

// zexel's planar mirror maps: in mirror-room (the teapot turns, the box slides, the light swings
// in front of the wall mirror) the exact policy re-captures every change, the defaults skip a
// change below the tolerances and take at most the probe budget (one mirror) a frame.
TEST_F(Recapture, ZexelMirrorMapsFollowThePolicy) {
  const Scene scene = makeBuiltinScene("mirror-room", {});
  FrameRenderer renderer(scene, kSize);
  const View view(scene.camera(), kSize);
  FrameSettings settings;
  auto exact = renderer.createMethod("zexel", kExact, settings);
  auto amortised = renderer.createMethod("zexel", {}, settings);
  const auto captures = [&](Method& m, float time) {
    Counts c;
    renderer.render(m, view, time, settings, nullptr, &c);
    return c.at("zexel_captures");
  };
  EXPECT_EQ(captures(*exact, 0.0f), 1.0);
  EXPECT_EQ(captures(*amortised, 0.0f), 1.0);
  // 1 ms: the light turns 0.03°, the teapot 0.05°: below 1 degree and 2 texels.
  EXPECT_EQ(captures(*exact, 0.001f), 1.0);
  EXPECT_EQ(captures(*amortised, 0.001f), 0.0);
  // 0.5 s: everything moved well beyond the tolerances.
  EXPECT_EQ(captures(*exact, 0.5f), 1.0);
  const RenderedFrame exact_frame = renderer.read();
  EXPECT_EQ(captures(*amortised, 0.5f), 1.0);
  EXPECT_TRUE(
      imagesEqual(renderer.read().color, exact_frame.color, 0.0f, &exact_frame.ids, "amortised"));
  const RenderedFrame b = fresh(renderer, "zexel", 0.5f);
  EXPECT_TRUE(imagesEqual(exact_frame.color, b.color, 0.0f, &b.ids, "zexel-exact"));
}

}  // namespace
}  // namespace mirage::test
