// render() computes less per hit than the straightforward loop it replaced (per-instance normal
// matrices and per-material data computed once, no position or geometric normal for diffuse
// shading, the centre sample reused as the pixel-centre ray): the ground truth must not change
// by a single bit — colour, distance, ids and ray counts — for one sample per pixel and for
// supersampling, on full tiles and partial ones.
#include <gtest/gtest.h>

#include <cstring>

#include "raytrace/tracer.h"
#include "scene/builtin_scenes.h"

namespace mirage {
namespace {

struct IdentityCase {
  const char* scene;
  ivec2 size;
  int spp;
  int order;
};

void PrintTo(const IdentityCase& c, std::ostream* os) {
  *os << c.scene << " " << c.size.x << "x" << c.size.y << " spp " << c.spp << " order " << c.order;
}

class RenderIdentity : public ::testing::TestWithParam<IdentityCase> {};

TEST_P(RenderIdentity, RenderMatchesTheReferenceBitForBit) {
  const IdentityCase& c = GetParam();
  Scene scene = makeBuiltinScene(c.scene);
  EnvironmentMap env = EnvironmentMap::forScene(scene);
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  View view(scene.camera(), c.size);
  const TraceSettings settings{c.order, c.spp};
  TraceResult want = tracer.renderReference(view, settings);
  TraceResult got = tracer.render(view, settings);

  ASSERT_EQ(got.color.size(), want.color.size());
  ASSERT_EQ(got.ids.size(), want.ids.size());
  int differing = 0;
  for (int y = 0; y < c.size.y; ++y)
    for (int x = 0; x < c.size.x; ++x) {
      const vec4 &g = got.color(x, y), &w = want.color(x, y);
      // Bits, not values: -0 against +0 or one NaN against another would be a change too.
      if (std::memcmp(&g, &w, sizeof(vec4)) != 0 || got.ids(x, y) != want.ids(x, y)) {
        if (++differing <= 5)
          ADD_FAILURE() << "pixel " << x << "," << y << ": render (" << g.x << ", " << g.y << ", "
                        << g.z << ", " << g.w << ") id " << got.ids(x, y) << ", reference (" << w.x
                        << ", " << w.y << ", " << w.z << ", " << w.w << ") id " << want.ids(x, y);
      }
    }
  EXPECT_EQ(differing, 0) << "pixels that differ from the reference";
  EXPECT_EQ(got.stats.primary_rays, want.stats.primary_rays);
  EXPECT_EQ(got.stats.reflected_rays, want.stats.reflected_rays);
  EXPECT_EQ(got.stats.primary_rays, uint64_t(c.size.x) * uint64_t(c.size.y) * uint64_t(c.spp));
  // Both scenes show mirrors: the comparison covers reflected rays unless the order is 0.
  if (c.order > 0) {
    EXPECT_GT(got.stats.reflected_rays, 0u);
  }
}

// Full-size frames, partial tiles (sizes not multiples of 16), even and odd sample grids (an
// odd one has a sample at the pixel centre), spp that fills no square, orders 0 to 3.
INSTANTIATE_TEST_SUITE_P(BuiltinScenes, RenderIdentity,
                         ::testing::Values(IdentityCase{"sphere-over-checker", {720, 512}, 1, 2},
                                           IdentityCase{"spheres9", {720, 512}, 1, 2},
                                           IdentityCase{"sphere-over-checker", {203, 141}, 4, 2},
                                           IdentityCase{"spheres9", {203, 141}, 9, 3},
                                           IdentityCase{"spheres9", {160, 120}, 5, 1},
                                           IdentityCase{"sphere-over-checker", {97, 65}, 9, 1},
                                           IdentityCase{"sphere-over-checker", {96, 64}, 2, 0}));

// Rendering into a result that holds an earlier frame (other samples, other order) of the same
// size reuses its images; nothing of the earlier frame may survive.
TEST(RenderReuse, ReusedImagesGiveTheReferenceFrame) {
  Scene scene = makeBuiltinScene("spheres9");
  EnvironmentMap env = EnvironmentMap::forScene(scene);
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  View view(scene.camera(), {150, 100});
  TraceResult out;
  tracer.render(View(scene.camera(), {60, 40}), {1, 1}, out);
  tracer.render(view, {3, 4}, out);
  tracer.render(view, {2, 1}, out);
  TraceResult want = tracer.renderReference(view, {2, 1});
  ASSERT_EQ(out.color.size(), want.color.size());
  EXPECT_EQ(
      std::memcmp(out.color.data(), want.color.data(), want.color.pixelCount() * sizeof(vec4)), 0);
  EXPECT_EQ(out.ids.pixels(), want.ids.pixels());
  EXPECT_EQ(out.stats.primary_rays, want.stats.primary_rays);
  EXPECT_EQ(out.stats.reflected_rays, want.stats.reflected_rays);
}

TEST(RenderStats, DirectAndReflectSharesSplitTheFrameTime) {
  Scene scene = makeBuiltinScene("spheres9");
  EnvironmentMap env = EnvironmentMap::forScene(scene);
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  TraceResult r = tracer.render(View(scene.camera(), {160, 112}), {2, 1});
  EXPECT_GT(r.stats.ms, 0.0);
  EXPECT_GT(r.stats.direct_ms, 0.0);
  EXPECT_GT(r.stats.reflect_ms, 0.0);
  EXPECT_NEAR(r.stats.direct_ms + r.stats.reflect_ms, r.stats.ms, 1e-6 * r.stats.ms);
}

}  // namespace
}  // namespace mirage
