// The alpha-tested nearest billboard hit (methods/billboard/billboard_nearest_shared.h) and the
// footprint of a hit, on the CPU: billboard.frag runs this very code over its storage buffers.
#include <gtest/gtest.h>

#include <vector>

#include "methods/billboard/billboard_shared.h"

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

#include "methods/billboard/billboard_nearest_shared.h"

namespace mirage {
namespace {

using shading::BillboardData;

// A 2 x 2 billboard in the plane z = `z`, centred on the z axis.
BillboardData wallAt(float z, int layer) {
  BillboardData b{};
  b.corner = vec4(-1, -1, z, 0);
  b.edge_u = vec4(2, 0, 0, 0);
  b.edge_v = vec4(0, 2, 0, 0);
  b.info = ivec4(MIRAGE_BILLBOARD_DIFFUSE, layer, -1, -1);
  return b;
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

TEST(BillboardFootprint, MatchesFiniteDifferences) {
  // A slanted billboard and a ray meeting it obliquely: the uv differential must equal the uv
  // change of a slightly moved ray, to first order.
  BillboardData b{};
  b.corner = vec4(-2, 0, -6, 0);
  b.edge_u = vec4(4, 0, 0, 0);
  b.edge_v = vec4(0, 3, 2, 0);
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
