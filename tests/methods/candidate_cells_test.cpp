// Candidate lists per direction cell (--impostor-cells): the cell lookup the shaders run
// (billboard_shared.h) against the cones the lists are built for, the reach test against
// sampled rays, the covered region of a billboard against projected points, and the lists of a
// placed billboard set.
#include <gtest/gtest.h>

#include <random>

#include "methods/impostor/billboard_set.h"
#include "methods/impostor/candidate_cells.h"
#include "scene/builtin_scenes.h"

namespace mirage::test {
namespace {

vec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<float> n;
  for (;;) {
    const vec3 v(n(rng), n(rng), n(rng));
    if (glm::length(v) > 1e-3f) return glm::normalize(v);
  }
}

vec3 randomInBall(std::mt19937& rng, const BoundingSphere& s) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  return s.centre + randomDirection(rng) * s.radius * std::cbrt(u(rng));
}

float angle(const vec3& a, const vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

// Every direction lies in the cone of the cell the shaders' lookup gives it, and every cell is
// used.
TEST(CandidateCells, EveryDirectionLiesInItsCellsCone) {
  std::mt19937 rng(7);
  for (int g : {1, 2, 4, 8, 16}) {
    const int cells = shading::direction_cell_count(g);
    ASSERT_EQ(cells, 6 * g * g);
    std::vector<int> used(size_t(cells), 0);
    for (int i = 0; i < 20000; ++i) {
      const vec3 d = randomDirection(rng) * 3.0f;  // any length
      const int cell = shading::direction_cell(d, g);
      ASSERT_GE(cell, 0);
      ASSERT_LT(cell, cells);
      const DirectionCone cone = directionCellCone(cell, g);
      ASSERT_LE(angle(cone.axis, d), cone.half_angle) << "g " << g << " cell " << cell;
      ASSERT_LT(cone.half_angle, kPi / 2);
      used[size_t(cell)]++;
    }
    if (g <= 8) {
      EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "g " << g;
    }
  }
  // Axis directions and cube corners (the faces' borders) land in a cell holding them.
  for (const vec3 d :
       {vec3(1, 0, 0), vec3(0, -1, 0), vec3(1, 1, 1), vec3(-1, 1, -1), vec3(1, 1, 0)})
    for (int g : {1, 3, 8}) {
      const DirectionCone cone = directionCellCone(shading::direction_cell(d, g), g);
      EXPECT_LE(angle(cone.axis, d), cone.half_angle);
    }
  EXPECT_EQ(shading::direction_cell(vec3(0.3f, -2.0f, 5.0f), 0), 0);
  EXPECT_EQ(shading::direction_cell_count(0), 1);
}

// A ray from a point of one sphere along a direction of a cell that meets the other sphere is
// never refused; the test refuses most pairs that no sampled ray of the cell connects.
TEST(CandidateCells, ReachKeepsEveryRayThatMeetsTheTarget) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int g = 4;
  int refused = 0, pairs = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const BoundingSphere from{vec3(0.0f), 0.2f + u(rng)};
    const BoundingSphere to{randomDirection(rng) * (0.5f + 6.0f * u(rng)), 0.1f + u(rng)};
    const int cell = int(u(rng) * float(shading::direction_cell_count(g) - 1));
    const DirectionCone cone = directionCellCone(cell, g);
    const bool reach = mayReach(from, cone, to);
    ++pairs;
    if (!reach) ++refused;
    // Rays from sampled points to sampled points of the target, in the cell: none may exist
    // when the test refuses.
    for (int k = 0; k < 200 && !reach; ++k) {
      const vec3 dir = randomInBall(rng, to) - randomInBall(rng, from);
      ASSERT_NE(shading::direction_cell(dir, g), cell)
          << "a ray of the cell meets the target, yet the test refused it (trial " << trial << ")";
    }
  }
  EXPECT_GT(refused, pairs / 4) << "the test should refuse the far-off cells";
  // One cell, every direction: everything is reachable.
  EXPECT_TRUE(mayReach({vec3(0.0f), 1.0f}, directionCellCone(0, 0), {vec3(9.0f), 0.1f}));
}

// A billboard's coverage: the points of an object sphere projected from the capture camera onto
// the quad's plane through its centre all lie within the covered sphere.
TEST(CandidateCells, CoveredSphereHoldsTheObjectsProjection) {
  std::mt19937 rng(3);
  for (float distance : {3.0f, 11.5f, 40.0f}) {
    const BoundingSphere object{vec3(1.0f, 2.0f, -0.5f), 1.0f};
    const vec3 towards = glm::normalize(vec3(0.3f, 0.2f, 1.0f));
    const vec3 camera = object.centre + towards * distance;
    const BoundingSphere covered = coveredSphere(object, distance, 0.0f);
    float widest = 0.0f;
    for (int i = 0; i < 20000; ++i) {
      const vec3 x = object.centre + randomDirection(rng) * object.radius;  // on its surface
      const vec3 ray = x - camera;
      const float t = glm::dot(object.centre - camera, towards) / glm::dot(ray, towards);
      const vec3 q = camera + t * ray;
      widest = std::max(widest, glm::length(q - object.centre));
    }
    EXPECT_LE(widest, covered.radius) << "camera at " << distance;
    EXPECT_GT(widest, 0.97f * covered.radius / 1.01f) << "the bound is tight";
  }
  // A texel's width more: a texel counts as covered wherever any of its points is.
  EXPECT_NEAR(coveredSphere({vec3(0.0f), 1.0f}, 1e6f, 0.5f).radius,
              (1.0f + std::sqrt(2.0f) * 0.5f) * 1.01f, 1e-4f);
}

// The sphere about a round reflector's bounds centre that holds its vertices is its own.
TEST(CandidateCells, VertexSphereOfASphereIsItsRadius) {
  const Scene scene = makeBuiltinScene("spheres9");
  const std::vector<BoundingSphere> spheres = reflectorVertexSpheres(scene, 0.0f);
  ASSERT_EQ(spheres.size(), 9u);
  for (size_t k = 0; k < spheres.size(); ++k) {
    EXPECT_NEAR(spheres[k].radius, 0.7f, 1e-3f);
    const Bounds3 b = scene.instanceBounds(scene.reflectorInstances()[k], 0.0f);
    EXPECT_LT(spheres[k].radius, 0.6f * b.radius() + 0.3f) << "tighter than the box's";
  }
}

// Each cell's list holds a part of the reflector's single list, and on spheres9 the parts are
// much shorter than the whole.
TEST(CandidateCells, CellListsAreShortPartsOfTheWholeList) {
  const Scene scene = makeBuiltinScene("spheres9");
  BillboardSetOptions whole, cells;
  cells.cells = 8;
  const BillboardSet one = placeBillboards(scene, 0.0f, whole);
  const BillboardSet many = placeBillboards(scene, 0.0f, cells);
  ASSERT_EQ(one.billboards.size(), many.billboards.size());
  const int per = shading::direction_cell_count(8);
  ASSERT_EQ(many.ranges.size(), one.ranges.size() * size_t(per));
  double listed = 0.0, total = 0.0;
  for (size_t r = 0; r < one.ranges.size(); ++r) {
    const ivec4 all = one.ranges[r].range;
    std::vector<int> whole_list(one.entries.begin() + all.x,
                                one.entries.begin() + all.x + all.y + all.w);
    for (int cell = 0; cell < per; ++cell) {
      const ivec4 part = many.ranges[r * size_t(per) + size_t(cell)].range;
      EXPECT_EQ(part.z, part.x + part.y);
      for (int k = part.x; k < part.x + part.y + part.w; ++k)
        EXPECT_NE(std::find(whole_list.begin(), whole_list.end(), many.entries[size_t(k)]),
                  whole_list.end());
      listed += part.y + part.w;
      total += all.y + all.w;
    }
  }
  EXPECT_LT(listed, 0.5 * total);
}

}  // namespace
}  // namespace mirage::test
