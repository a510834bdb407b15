// The hybrid method's splats leave no holes where a concave mirror magnifies an object: its
// points are stratified over the surface and each splat is as large as the gap to its own
// neighbours, so that a magnified ball is covered. A splat of a nearer part of a reflector never
// wins on a farther part's pixels beside its silhouette. Images written on failure.
#include <gtest/gtest.h>

#include <cstdio>
#include <utility>

#include "core/first_hit.h"
#include "methods/frame.h"
#include "raytrace/tracer.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class HybridHoles : public GlTest {};

// hybrid's frame of the scene at order 1 and the ray tracer's first hits of its reflected rays.
std::pair<RenderedFrame, IdImage> hybridFrameAndFirstHits(const Scene& scene, ivec2 size) {
  FrameSettings settings;
  settings.order = 1;
  FrameRenderer renderer(scene, size);
  auto m = renderer.createMethod("hybrid", {}, settings);
  const View view(scene.camera(), size);
  renderer.render(*m, view, 0.0f, settings);
  RayTracer tracer(scene, renderer.environment());
  tracer.prepare(0.0f);
  return {renderer.read(), tracer.firstHits(view, 1)};
}

// concave-dish with its ball pure green: a pixel whose reflected ray meets the ball (the ray
// tracer's first hits) and that shows no green splat shows the background cube map (the sky and
// the dish), whose blue a splat of the ball has not.
TEST_F(HybridHoles, AMagnifiedBallIsCoveredByItsSplats) {
  Scene scene = makeBuiltinScene("concave-dish");
  const int ball = instanceNamed(scene, "ball");
  ASSERT_GE(ball, 0);
  scene.materials[size_t(scene.instances[size_t(ball)].material)] =
      Material::diffuse("green", {0.0f, 0.9f, 0.0f});
  const ivec2 size{320, 240};
  const auto [frame, hits] = hybridFrameAndFirstHits(scene, size);
  size_t ball_pixels = 0, empty = 0;
  Image holes(size.x, size.y, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const uint32_t code = hits(x, y);
      if (firstHitKind(code) != FirstHit::kDiffuse || firstHitInstance(code) != ball) continue;
      ++ball_pixels;
      const vec4 c = frame.color(x, y);
      const bool hole = c.z > 0.25f * c.y;  // the background's blue, no green splat
      empty += hole ? 1 : 0;
      holes(x, y) = hole ? vec4(1.0f, 0.0f, 0.0f, 1.0f) : vec4(0.0f, 1.0f, 0.0f, 1.0f);
    }
  const double fraction = double(empty) / double(std::max<size_t>(ball_pixels, 1));
  std::printf("concave-dish: %zu of %zu ball pixels empty (%.2f %%)\n", empty, ball_pixels,
              100.0 * fraction);
  ASSERT_GT(ball_pixels, 2000u) << "the dish magnifies the ball";
  if (fraction > 0.01) writeArtifacts(holes, displayed(frame.color), "holes");
  EXPECT_LE(fraction, 0.01);
}

// Two mirror spheres, the nearer (A) overlapping the farther (B, ten times as far) on screen,
// before a red slab (a box: point-sampled, where a flat wall would be in the background cube
// map) far behind them: A's reflections by its silhouette, turned outwards past B, see the slab;
// B's pixels beside that silhouette face the eye and see the sky behind it. A splat of A's
// silhouette that spilled onto B's pixels there would show red where B's reflected rays leave
// the scene.
Scene overlappingMirrorsBeforeAWall() {
  Scene s;
  s.name = "overlapping-mirrors";
  const int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "near", addMesh(s, procedural::sphere(0.25f, 96, 48)), mirror,
              placeAt({-0.15f, 1.0f, 4.0f}));
  addInstance(s, "far", addMesh(s, procedural::sphere(1.5f, 96, 48)), mirror,
              placeAt({0.9f, 1.0f, -14.0f}));
  const int red = addMaterial(s, Material::diffuse("red", {0.9f, 0.0f, 0.0f}));
  addInstance(s, "slab", addMesh(s, procedural::box({20.0f, 15.0f, 0.5f})), red,
              placeAt({0.0f, 1.0f, -30.0f}));
  finishScene(s, vec3{0.0f, 1.0f, 6.0f}, vec3{0.0f, 1.0f, 0.0f}, 40.0f);
  return s;
}

TEST_F(HybridHoles, NoSplatOfANearerReflectorWinsBesideItsSilhouette) {
  const Scene scene = overlappingMirrorsBeforeAWall();
  const int slab = instanceNamed(scene, "slab");
  const ivec2 size{400, 300};
  const auto [frame, hits] = hybridFrameAndFirstHits(scene, size);
  // The near sphere's ID: the first reflector pixel from the left on the middle row (both
  // centres lie on the eye's level, the near one to the left).
  uint32_t near_id = 0;
  for (int x = 0; x < size.x && near_id == 0; ++x) near_id = frame.ids(x, size.y / 2);
  ASSERT_NE(near_id, 0u);
  constexpr int kBand = 8;  // twice the largest splat's half side (MIRAGE_HYBRID_MAX_SPLAT)
  size_t band = 0, bled = 0, slab_pixels = 0;
  Image marks(size.x, size.y, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const uint32_t id = frame.ids(x, y);
      const uint32_t code = hits(x, y);
      if (id == near_id && firstHitInstance(code) == slab) ++slab_pixels;
      if (id == 0 || id == near_id || firstHitKind(code) != FirstHit::kEnvironment) continue;
      // Beside the near sphere, and not beside the far one's own silhouette (whose grazing
      // reflections see the slab: its own splats may spill a pixel there).
      bool beside_near = false, beside_edge = false;
      for (int dy = -kBand; dy <= kBand; ++dy)
        for (int dx = -kBand; dx <= kBand; ++dx) {
          const ivec2 q{x + dx, y + dy};
          if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
          beside_near |= frame.ids(q.x, q.y) == near_id;
          beside_edge |= frame.ids(q.x, q.y) == 0;
        }
      if (!beside_near || beside_edge) continue;
      ++band;
      const vec4 c = frame.color(x, y);
      const bool red = c.x > c.y + 0.2f && c.x > c.z + 0.2f;
      bled += red ? 1 : 0;
      marks(x, y) = red ? vec4(1.0f, 0.0f, 0.0f, 1.0f) : vec4(0.0f, 1.0f, 0.0f, 1.0f);
    }
  std::printf(
      "%zu of the far sphere's %zu sky pixels beside the near one show the slab "
      "(the near one shows it on %zu)\n",
      bled, band, slab_pixels);
  ASSERT_GT(slab_pixels, 150u) << "the near sphere's silhouette reflects the slab";
  ASSERT_GT(band, 200u) << "the far sphere shows sky beside the near one";
  if (bled > 0) writeArtifacts(marks, displayed(frame.color), "bleeding");
  EXPECT_EQ(bled, 0u);
}

}  // namespace
}  // namespace mirage::test
