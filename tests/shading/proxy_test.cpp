// The proxy intersections of shading/proxy.h (box exit, billboard quad, parallax lookup, the
// billboard-to-environment morph) against hand-computed cases: the shaders run this very code.
#include <gtest/gtest.h>

#include <cmath>

#include "shading/proxy.h"

namespace mirage {
namespace {

using shading::box_parallax_direction;
using shading::morph_direction;
using shading::ray_box_exit;
using shading::ray_quad;

void expectVec(const vec3& got, const vec3& want, float tolerance = 1e-5f) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST(RayBoxExit, FromInsideLeavesThroughTheFaceAhead) {
  const vec3 lo(-1.0f), hi(1.0f);
  int face = -2;
  EXPECT_FLOAT_EQ(ray_box_exit(vec3(0), vec3(1, 0, 0), lo, hi, face), 1.0f);
  EXPECT_EQ(face, MIRAGE_BOX_MAX_X);
  EXPECT_FLOAT_EQ(ray_box_exit(vec3(0), vec3(0, -1, 0), lo, hi, face), 1.0f);
  EXPECT_EQ(face, MIRAGE_BOX_MIN_Y);
  EXPECT_FLOAT_EQ(ray_box_exit(vec3(0, 0, 0.5f), vec3(0, 0, -1), lo, hi, face), 1.5f);
  EXPECT_EQ(face, MIRAGE_BOX_MIN_Z);
  // Oblique: (2, 1, 0)/sqrt(5) reaches x = 1 at t = sqrt(5)/2, before y = 1 at sqrt(5).
  vec3 d = glm::normalize(vec3(2, 1, 0));
  EXPECT_NEAR(ray_box_exit(vec3(0), d, lo, hi, face), std::sqrt(5.0f) / 2.0f, 1e-6f);
  EXPECT_EQ(face, MIRAGE_BOX_MAX_X);
}

TEST(RayBoxExit, FromOutsideEntersThenLeaves) {
  const vec3 lo(-1.0f), hi(1.0f);
  int face = -2;
  EXPECT_FLOAT_EQ(ray_box_exit(vec3(-3, 0, 0), vec3(1, 0, 0), lo, hi, face), 4.0f);
  EXPECT_EQ(face, MIRAGE_BOX_MAX_X);
  // From above, straight down: through the top and out at the bottom.
  EXPECT_FLOAT_EQ(ray_box_exit(vec3(0.2f, 5, 0.3f), vec3(0, -1, 0), lo, hi, face), 6.0f);
  EXPECT_EQ(face, MIRAGE_BOX_MIN_Y);
}

TEST(RayBoxExit, MissesAndBoxesBehindGiveMinusOne) {
  const vec3 lo(-1.0f), hi(1.0f);
  int face = 7;
  EXPECT_EQ(ray_box_exit(vec3(-3, 0, 0), vec3(-1, 0, 0), lo, hi, face), -1.0f);  // behind
  EXPECT_EQ(face, -1);
  EXPECT_EQ(ray_box_exit(vec3(-3, 2, 0), vec3(1, 0, 0), lo, hi, face), -1.0f);  // passes above
  EXPECT_EQ(ray_box_exit(vec3(-3, 0, 0), glm::normalize(vec3(1, 1, 0)), lo, hi, face), -1.0f);
}

TEST(RayBoxExit, AxisParallelRaysGiveNoNaN) {
  int face = -2;
  float t = ray_box_exit(vec3(1, 1, 1), vec3(0, 0, -1), vec3(0), vec3(4, 2, 4), face);
  EXPECT_FLOAT_EQ(t, 1.0f);
  EXPECT_EQ(face, MIRAGE_BOX_MIN_Z);
  // Parallel to a slab and outside it: a miss, not NaN.
  EXPECT_EQ(ray_box_exit(vec3(5, 1, 1), vec3(0, 0, -1), vec3(0), vec3(4, 2, 4), face), -1.0f);
}

TEST(RayQuad, HitsInsideWithItsCoordinates) {
  // The quad y = 0, x in [0, 2], z in [0, 3].
  const vec3 corner(0), eu(2, 0, 0), ev(0, 0, 3);
  vec2 uv(-1.0f);
  EXPECT_FLOAT_EQ(ray_quad(vec3(1, 5, 1.5f), vec3(0, -1, 0), corner, eu, ev, 0.0f, uv), 5.0f);
  EXPECT_FLOAT_EQ(uv.x, 0.5f);
  EXPECT_FLOAT_EQ(uv.y, 0.5f);
  // From below: both sides count.
  EXPECT_FLOAT_EQ(ray_quad(vec3(1, -2, 1.5f), vec3(0, 1, 0), corner, eu, ev, 0.0f, uv), 2.0f);
  // Oblique: (0, 1, 0) + t (1, -1, 1) meets y = 0 at t = 1, the point (1, 0, 1).
  EXPECT_FLOAT_EQ(ray_quad(vec3(0, 1, 0), vec3(1, -1, 1), corner, eu, ev, 0.0f, uv), 1.0f);
  EXPECT_FLOAT_EQ(uv.x, 0.5f);
  EXPECT_NEAR(uv.y, 1.0f / 3.0f, 1e-6f);
}

TEST(RayQuad, MissesOutsideParallelAndBehind) {
  const vec3 corner(0), eu(2, 0, 0), ev(0, 0, 3);
  vec2 uv;
  EXPECT_EQ(ray_quad(vec3(3, 5, 1), vec3(0, -1, 0), corner, eu, ev, 0.0f, uv), -1.0f);
  EXPECT_EQ(ray_quad(vec3(1, 5, -0.1f), vec3(0, -1, 0), corner, eu, ev, 0.0f, uv), -1.0f);
  EXPECT_EQ(ray_quad(vec3(1, 1, 1), vec3(1, 0, 0), corner, eu, ev, 0.0f, uv), -1.0f);
  EXPECT_EQ(ray_quad(vec3(1, 5, 1), vec3(0, 1, 0), corner, eu, ev, 0.0f, uv), -1.0f);
  // t_min excludes the quad a ray leaves from (t = 1e-7 here).
  EXPECT_EQ(ray_quad(vec3(1, 1e-7f, 1), vec3(0, -1, 0), corner, eu, ev, 1e-4f, uv), -1.0f);
}

TEST(BoxParallax, LooksUpTheWallPointTheRayReaches) {
  // A 4 x 4 x 4 room, probe at its centre, a reflector point off-centre looking at +Z.
  const vec3 lo(-2, 0, -2), hi(2, 4, 2), centre(0, 2, 0), origin(1, 1, 0);
  float t = 0.0f;
  vec3 d = box_parallax_direction(origin, vec3(0, 0, 1), lo, hi, centre, t);
  EXPECT_FLOAT_EQ(t, 2.0f);
  expectVec(d, vec3(1, -1, 2));  // from the centre to the wall point (1, 1, 2)
  // The corrected direction, traced from the probe's centre, reaches that very point.
  int face = -1;
  float s = ray_box_exit(centre, glm::normalize(d), lo, hi, face);
  expectVec(centre + s * glm::normalize(d), vec3(1, 1, 2));
  // A ray that misses the box (origin outside, pointing away) keeps its own direction.
  d = box_parallax_direction(vec3(0, 9, 0), vec3(0, 1, 0), lo, hi, centre, t);
  EXPECT_EQ(t, -1.0f);
  expectVec(d, vec3(0, 1, 0));
}

TEST(RaySphereExit, FarRootInsideAndOutside) {
  // Unit sphere at (0, 0, 0): from the centre every direction leaves at t = 1.
  EXPECT_FLOAT_EQ(shading::ray_sphere_exit(vec3(0), vec3(0, 1, 0), vec3(0), 1.0f), 1.0f);
  // From (0.5, 0, 0) along +x: leaves at x = 1.
  EXPECT_FLOAT_EQ(shading::ray_sphere_exit(vec3(0.5f, 0, 0), vec3(1, 0, 0), vec3(0), 1.0f), 0.5f);
  // From outside, through it: the far side (x = 1 from x = -3 is t = 4).
  EXPECT_FLOAT_EQ(shading::ray_sphere_exit(vec3(-3, 0, 0), vec3(1, 0, 0), vec3(0), 1.0f), 4.0f);
  // Missing it, or leaving it behind: -1.
  EXPECT_EQ(shading::ray_sphere_exit(vec3(-3, 2, 0), vec3(1, 0, 0), vec3(0), 1.0f), -1.0f);
  EXPECT_EQ(shading::ray_sphere_exit(vec3(3, 0, 0), vec3(1, 0, 0), vec3(0), 1.0f), -1.0f);
  // Sphere parallax: from (0, 0.5, 0) along +x the wall point is (sqrt(0.75), 0.5, 0).
  float t = 0.0f;
  vec3 d = shading::sphere_parallax_direction(vec3(0, 0.5f, 0), vec3(1, 0, 0), vec3(0), 1.0f,
                                              vec3(0), t);
  EXPECT_NEAR(t, std::sqrt(0.75f), 1e-6f);
  expectVec(d, vec3(std::sqrt(0.75f), 0.5f, 0.0f));
}

TEST(Morph, BlendsFromTheBillboardToTheEnvironment) {
  const vec3 hit(2, 0, 0), centre(0), dir(0, 3, 0);
  expectVec(morph_direction(hit, centre, dir, 0.0f, 1.0f), vec3(1, 0, 0));  // h = 0: r_a
  expectVec(morph_direction(hit, centre, dir, 1.0f, 1.0f), vec3(0, 1, 0));  // h = H: r_d
  const float s = std::sqrt(0.5f);
  expectVec(morph_direction(hit, centre, dir, 0.5f, 1.0f), vec3(s, s, 0));  // halfway
  // Outside [0, H] the blend is clamped.
  expectVec(morph_direction(hit, centre, dir, 2.0f, 1.0f), vec3(0, 1, 0));
  expectVec(morph_direction(hit, centre, dir, -1.0f, 1.0f), vec3(1, 0, 0));
}

}  // namespace
}  // namespace mirage
