// The alpha-tested nearest billboard hit (methods/impostor/billboard_nearest_shared.h) and the
// footprint of a hit, on the CPU: billboard.frag runs this very code over its storage buffers.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "methods/impostor/billboard_shared.h"

// The accessors the shared search reads billboards through (the shader's read buffers and
// textures). Coverage: each billboard is opaque but for a square hole in its middle.
namespace mirage::shading {
namespace {
std::vector<BillboardData> g_billboards;
std::vector<int> g_entries;
}  // namespace
inline BillboardData billboard_data(int index) {
  return g_billboards[size_t(index)];
}
inline int billboard_list_entry(int position) {
  return g_entries[size_t(position)];
}
inline float billboard_coverage(BillboardData, vec2 uv) {
  return std::abs(uv.x - 0.5f) < 0.2f && std::abs(uv.y - 0.5f) < 0.2f ? 0.0f : 1.0f;
}
}  // namespace mirage::shading

#include "methods/impostor/billboard_nearest_shared.h"

namespace mirage {
namespace {

using shading::BillboardData;

// A 2 x 2 billboard in the plane z = `z`, centred on the z axis.
BillboardData wallAt(float z, int layer) {
  return shading::make_billboard(vec3(-1, -1, z), vec3(2, 0, 0), vec3(0, 2, 0),
                                 ivec4(MIRAGE_BILLBOARD_DIFFUSE, layer, -1, -1));
}

class NearestBillboard : public ::testing::Test {
 protected:
  void SetUp() override {
    // Entries: 0 -> far wall (z = -5), 1 -> near wall (z = -2), 2 -> a wall behind the origin.
    shading::g_billboards = {wallAt(-5.0f, 0), wallAt(-2.0f, 1), wallAt(3.0f, 2)};
    shading::g_entries = {0, 1, 2};
  }
  int nearest(vec3 origin, vec3 dir, int first, int count, float& t, vec2& uv) {
    return shading::nearest_billboard(origin, dir, first, count, 1e-4f, t, uv);
  }
};

TEST_F(NearestBillboard, TakesTheNearestOpaqueHit) {
  float t = 1e30f;
  vec2 uv(-1.0f);
  // Through the opaque border of both walls: the near one wins, whatever the list order.
  EXPECT_EQ(nearest(vec3(0.8f, 0.0f, 0.0f), vec3(0, 0, -1), 0, 3, t, uv), 1);
  EXPECT_FLOAT_EQ(t, 2.0f);
  EXPECT_FLOAT_EQ(uv.x, 0.9f);
  EXPECT_FLOAT_EQ(uv.y, 0.5f);
}

TEST_F(NearestBillboard, AlphaHolesLetTheRayThrough) {
  float t = 1e30f;
  vec2 uv;
  // Through the hole of the near wall (uv 0.5, 0.5), and of the far wall too: no hit.
  EXPECT_EQ(nearest(vec3(0.0f), vec3(0, 0, -1), 0, 3, t, uv), -1);
  EXPECT_EQ(t, 1e30f);
  // Slanted so that it passes the near wall's hole and meets the far wall's border.
  vec3 dir = glm::normalize(vec3(0.15f, 0.0f, -1.0f));  // x = 0.3 at z = -2, 0.75 at z = -5
  EXPECT_EQ(nearest(vec3(0.0f), dir, 0, 3, t, uv), 0);
  EXPECT_NEAR(uv.x, 0.875f, 1e-5f);
}

TEST_F(NearestBillboard, OnlyTheGivenEntriesAndTheGivenInterval) {
  float t = 1e30f;
  vec2 uv;
  // Entries [0, 1): the far wall only.
  EXPECT_EQ(nearest(vec3(0.8f, 0, 0), vec3(0, 0, -1), 0, 1, t, uv), 0);
  EXPECT_FLOAT_EQ(t, 5.0f);
  // A hit no nearer than t_best is not taken (a closer billboard was found before).
  t = 1.5f;
  EXPECT_EQ(nearest(vec3(0.8f, 0, 0), vec3(0, 0, -1), 0, 3, t, uv), -1);
  EXPECT_EQ(t, 1.5f);
  // Behind the origin: only the wall at z = 3 in that direction.
  t = 1e30f;
  EXPECT_EQ(nearest(vec3(0.8f, 0, 0), vec3(0, 0, 1), 0, 3, t, uv), 2);
  EXPECT_FLOAT_EQ(t, 3.0f);
}

TEST(BillboardHit, AgreesWithTheGenericQuadIntersection) {
  // billboard_hit precomputes the plane and the inverse edge lengths; shading::ray_quad (tested
  // by hand in tests/shading) computes them per call. Random rays against random quads.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  auto rand3 = [&] { return vec3(u(rng), u(rng), u(rng)); };
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    vec3 eu = 2.0f * rand3(), helper = rand3();
    vec3 ev = glm::cross(glm::normalize(eu), helper) * 1.5f;  // perpendicular to eu
    vec3 corner = 2.0f * rand3();
    if (glm::length(eu) < 0.05f || glm::length(ev) < 0.05f) continue;
    BillboardData b = shading::make_billboard(corner, eu, ev, ivec4(0));
    vec3 o = 3.0f * rand3(),
         target = corner + (u(rng) * 0.6f + 0.5f) * eu + (u(rng) * 0.6f + 0.5f) * ev;
    vec3 d = glm::normalize(target - o);
    vec2 uv_a, uv_b;
    float ta = shading::billboard_hit(b, o, d, 1e-4f, uv_a);
    float tb = shading::ray_quad(o, d, corner, eu, ev, 1e-4f, uv_b);
    ASSERT_EQ(ta >= 0.0f, tb >= 0.0f) << "ray " << i << ": t " << ta << " vs " << tb;
    if (ta < 0.0f) continue;
    ++hits;
    // Float rounding, amplified at grazing incidence by 1 / |cos|.
    const float grazing = 1.0f / std::max(std::abs(glm::dot(d, vec3(b.plane))), 1e-3f);
    EXPECT_NEAR(ta, tb, 1e-5f * grazing * (1.0f + tb));
    EXPECT_NEAR(uv_a.x, uv_b.x, 1e-5f * grazing);
    EXPECT_NEAR(uv_a.y, uv_b.y, 1e-5f * grazing);
  }
  EXPECT_GT(hits, 5000);
}

TEST(BillboardFootprint, MatchesFiniteDifferences) {
  // A slanted billboard and a ray meeting it obliquely: the uv differential must equal the uv
  // change of a slightly moved ray, to first order.
  // edge_v is perpendicular to edge_u, as every billboard's.
  BillboardData b = shading::make_billboard(vec3(-2, 0, -6), vec3(4, 0, 0), vec3(0, 3, 2),
                                            ivec4(MIRAGE_BILLBOARD_DIFFUSE, 0, -1, -1));
  vec3 o(0.3f, 1.0f, 0.0f), d = glm::normalize(vec3(0.1f, 0.2f, -1.0f));
  vec3 d_origin(1e-3f, -2e-3f, 5e-4f), d_dir(2e-4f, 1e-4f, -3e-4f);
  vec2 uv0, uv1;
  float t = shading::billboard_hit(b, o, d, 0.0f, uv0);
  ASSERT_GT(t, 0.0f);
  ASSERT_GT(shading::billboard_hit(b, o + d_origin, d + d_dir, 0.0f, uv1), 0.0f);
  vec2 predicted = shading::billboard_uv_differential(b, d, t, d_origin, d_dir);
  EXPECT_NEAR(predicted.x, uv1.x - uv0.x, 2e-5f);
  EXPECT_NEAR(predicted.y, uv1.y - uv0.y, 2e-5f);
  EXPECT_GT(glm::length(predicted), 1e-4f);
}

}  // namespace
}  // namespace mirage
