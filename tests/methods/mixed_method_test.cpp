// Method `mixed`: each reflector by its assigned method, the direct part drawn once. An
// assignment of one method to every reflector must give that method's frame bit for bit, and in
// a composite every reflector's pixels must be those its own method draws alone: each method
// draws exactly its own reflectors, nothing of the others'.
#include <cstring>

#include <gtest/gtest.h>

#include "methods/assignment.h"
#include "methods/frame.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/image_check.h"

namespace mirage::test {
namespace {

class MixedMethod : public GlTest {};

RenderedFrame renderOnce(FrameRenderer& renderer, const std::string& method,
                         const std::map<std::string, std::string>& params, int order = 2) {
  FrameSettings settings;
  settings.order = order;
  auto m = renderer.createMethod(method, params, settings);
  const View view(renderer.scene().camera(), renderer.size());
  renderer.render(*m, view, 0.0f, settings);
  return renderer.read();
}

bool sameBits(const RenderedFrame& a, const RenderedFrame& b) {
  return a.color.pixelCount() == b.color.pixelCount() &&
         std::memcmp(a.color.data(), b.color.data(), a.color.pixelCount() * sizeof(vec4)) == 0 &&
         std::memcmp(a.ids.data(), b.ids.data(), a.ids.pixelCount() * sizeof(uint32_t)) == 0;
}

// Pixels of `frame` whose id is in `ids` (0: the direct part) that differ from `alone`.
size_t differing(const RenderedFrame& frame, const RenderedFrame& alone,
                 const std::vector<uint32_t>& ids) {
  size_t out = 0;
  for (size_t p = 0; p < frame.color.pixelCount(); ++p) {
    const uint32_t id = frame.ids.data()[p];
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) continue;
    if (std::memcmp(&frame.color.data()[p], &alone.color.data()[p], sizeof(vec4)) != 0) ++out;
  }
  return out;
}

TEST_F(MixedMethod, OneMethodForEveryReflectorIsThatMethodsFrameBitForBit) {
  for (const char* scene_name : {"gallery", "teapot-sphere"}) {
    const Scene scene = makeBuiltinScene(scene_name);
    FrameRenderer renderer(scene, {96, 64});
    for (const MethodEntry& entry : methodRegistry()) {
      if (!assignable(entry.info)) continue;
      SCOPED_TRACE(std::string(scene_name) + " " + entry.info.name);
      const RenderedFrame alone = renderOnce(renderer, entry.info.name, {});
      const RenderedFrame mixed =
          renderOnce(renderer, "mixed", {{"assign", "*=" + entry.info.name}});
      EXPECT_TRUE(sameBits(alone, mixed));
      if (!sameBits(alone, mixed)) writeArtifacts(mixed.color, alone.color, entry.info.name);
    }
  }
}

TEST_F(MixedMethod, EveryReflectorShowsWhatItsOwnMethodDrawsAlone) {
  const Scene scene = makeBuiltinScene("gallery");
  FrameRenderer renderer(scene, {180, 128});
  // Reflector ids: position in scene order + 1; the wall mirrors are the first two.
  const std::vector<uint32_t> walls = {1, 2}, curved = {3, 4, 5}, direct = {0};
  // In a composite planar's mirrored views show the curved reflectors through probes, as
  // --planar-curved probes does alone.
  const RenderedFrame planar = renderOnce(renderer, "planar", {{"planar-curved", "probes"}});
  for (const char* curved_method : {"none", "envmap-box", "depthmap"}) {
    SCOPED_TRACE(curved_method);
    const RenderedFrame alone = renderOnce(renderer, curved_method, {});
    const RenderedFrame mixed =
        renderOnce(renderer, "mixed",
                   {{"assign", std::string("mirror-back,mirror-left=planar;*=") + curved_method}});
    ASSERT_TRUE(std::memcmp(mixed.ids.data(), planar.ids.data(),
                            planar.ids.pixelCount() * sizeof(uint32_t)) == 0);
    size_t wall_pixels = 0, curved_pixels = 0;
    for (uint32_t id : mixed.ids.pixels()) {
      wall_pixels += id == 1 || id == 2;
      curved_pixels += id >= 3;
    }
    ASSERT_GT(wall_pixels, 1000u);
    ASSERT_GT(curved_pixels, 1000u);
    EXPECT_EQ(differing(mixed, planar, walls), 0u);
    EXPECT_EQ(differing(mixed, alone, curved), 0u);
    EXPECT_EQ(differing(mixed, alone, direct), 0u);
    // And they differ where the methods do: the composite is neither frame.
    EXPECT_GT(differing(planar, alone, walls), 100u);
  }
}

// `ssr` shades its reflectors in a screen-space pass over the G-buffer: inside a composite it
// touches only the pixels of its own reflectors (those its G-buffer names), never another
// method's, though its pass covers the whole viewport.
TEST_F(MixedMethod, ScreenSpaceReflectionsTouchOnlyTheirOwnReflectors) {
  const Scene scene = makeBuiltinScene("gallery");
  FrameRenderer renderer(scene, {180, 128});
  const std::vector<uint32_t> walls = {1, 2}, curved = {3, 4, 5}, direct = {0};
  const RenderedFrame planar = renderOnce(renderer, "planar", {{"planar-curved", "probes"}});
  // Either way round: whichever of the two draws first.
  for (const bool ssr_on_walls : {false, true}) {
    SCOPED_TRACE(ssr_on_walls ? "ssr on the walls" : "ssr on the curved reflectors");
    const std::string assign = ssr_on_walls ? "mirror-back,mirror-left=ssr;*=planar"
                                            : "mirror-back,mirror-left=planar;*=ssr";
    const RenderedFrame mixed = renderOnce(renderer, "mixed", {{"assign", assign}});
    const std::vector<uint32_t>& by_planar = ssr_on_walls ? curved : walls;
    const std::vector<uint32_t>& by_ssr = ssr_on_walls ? walls : curved;
    EXPECT_EQ(differing(mixed, planar, by_planar), 0u);
    EXPECT_EQ(differing(mixed, planar, direct), 0u);
    EXPECT_GT(differing(mixed, planar, by_ssr), 100u);  // ssr drew those
  }
}

TEST_F(MixedMethod, ATimedFrameGivesEachEntrysTime) {
  const Scene scene = makeBuiltinScene("gallery");
  FrameRenderer renderer(scene, {96, 64});
  FrameSettings settings;
  auto m = renderer.createMethod("mixed", {}, settings);  // the scene's own "reflections"
  const View view(scene.camera(), renderer.size());
  renderer.render(*m, view, 0.0f, settings);
  EXPECT_TRUE(m->partTimes().empty());  // untimed
  gpu::FrameTimer timer(gpu::Clock::kWall);
  renderer.render(*m, view, 0.0f, settings, &timer);
  const gpu::FrameTimes t = timer.takeResults().front();
  const std::vector<Method::PartTime> parts = m->partTimes();
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].label, "mirror-back,mirror-left=planar");
  EXPECT_EQ(parts[1].label, "*=envmap-box");
  double sum = 0.0;
  for (const auto& p : parts) {
    EXPECT_GT(p.ms, 0.0) << p.label;
    sum += p.ms;
  }
  EXPECT_LE(sum, t.part_ms[size_t(gpu::Part::kReflect)] + 1e-3);
}

TEST_F(MixedMethod, WithoutAnAssignmentItSaysWhereToGiveOne) {
  const Scene scene = makeBuiltinScene("teapot-sphere");
  FrameRenderer renderer(scene, {32, 32});
  try {
    renderer.createMethod("mixed", {}, FrameSettings{});
    FAIL() << "made without an assignment";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--assign"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mirage::test
