// The hybrid method's point spacing and stratified sampling (point_spacing.h) against brute force
// and analytic cases, and the level of detail's strides from the probe's counts
// (restrideByProjections in c3rc_frame.h) against their formula.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <random>

#include "methods/hybrid/c3rc_frame.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/point_spacing.h"

namespace mirage::test {
namespace {

std::vector<vec3> uniformSquare(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<vec3> p(n);
  for (vec3& q : p) q = vec3(u(rng), u(rng), 0.0f);
  return p;
}

// The distance from p[i] to its k-th nearest other point, by sorting all of them.
float kthNearest(const std::vector<vec3>& p, size_t i, int k) {
  std::vector<float> d;
  for (size_t j = 0; j < p.size(); ++j)
    if (j != i) d.push_back(glm::length(p[j] - p[i]));
  std::nth_element(d.begin(), d.begin() + (k - 1), d.end());
  return d[size_t(k - 1)];
}

TEST(HybridPointSpacing, EachPointsSpacingIsItsSixthNeighboursDistanceScaled) {
  const std::vector<vec3> p = uniformSquare(3000, 7);
  const float mean = std::sqrt(1.0f / 3000.0f);
  const float most = 4.0f * mean;
  const std::vector<float> s = neighbourSpacings(p, mean, most);
  ASSERT_EQ(s.size(), p.size());
  for (size_t i = 0; i < p.size(); i += 7)
    EXPECT_NEAR(s[i], std::min(kSpacingScale * kthNearest(p, i, kSpacingNeighbours), most), 1e-6f)
        << i;
  // A bound far beyond the points' reach: the search still ends at the true neighbours.
  const std::vector<float> unbounded = neighbourSpacings(p, mean, 1e9f);
  for (size_t i = 0; i < p.size(); i += 7)
    EXPECT_NEAR(unbounded[i], kSpacingScale * kthNearest(p, i, kSpacingNeighbours), 1e-6f) << i;
  // The cap holds for a stray point far from the rest.
  std::vector<vec3> stray = p;
  stray.push_back(vec3(40.0f, 0.0f, 0.0f));
  const std::vector<float> capped = neighbourSpacings(stray, mean, 4.0f * mean);
  EXPECT_FLOAT_EQ(capped.back(), 4.0f * mean);
}

TEST(HybridPointSpacing, OnAGridEverySpacingIsTheSameAnalyticDistance) {
  // A unit grid: a point's 6th nearest neighbour (inside the grid) is a diagonal one, √2 away.
  std::vector<vec3> p;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) p.push_back(vec3(float(x), float(y), 0.0f));
  const std::vector<float> s = neighbourSpacings(p, 1.0f, 100.0f);
  for (int y = 1; y < 39; ++y)
    for (int x = 1; x < 39; ++x)
      EXPECT_NEAR(s[size_t(y * 40 + x)], kSpacingScale * std::sqrt(2.0f), 1e-5f);
}

// The smallest distance between any two of `p` (brute force).
float closestPair(const std::vector<vec3>& p) {
  float best = 1e30f;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) best = std::min(best, glm::length(p[i] - p[j]));
  return best;
}

TEST(HybridPointSpacing, SampleEliminationKeepsTheFixedAndSpreadsTheRest) {
  const size_t target = 1000, fixed = 20;
  const std::vector<vec3> candidates = uniformSquare(2 * target, 11);
  const std::vector<uint32_t> kept = eliminateSamples(candidates, fixed, target, 1.0);
  ASSERT_EQ(kept.size(), target);
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
  for (uint32_t i = 0; i < fixed; ++i) EXPECT_EQ(kept[i], i) << "a fixed candidate was removed";
  EXPECT_EQ(kept, eliminateSamples(candidates, fixed, target, 1.0)) << "deterministic";
  std::vector<vec3> chosen, random(candidates.begin(), candidates.begin() + long(target));
  for (uint32_t i : kept) chosen.push_back(candidates[i]);
  // r_max: the largest Poisson-disk radius of 1000 points on the unit square (a hexagonal
  // packing's points lie 2 r_max apart). From twice as many candidates the elimination keeps the
  // free ones (the fixed may lie close to each other) more than 0.8 r_max apart (measured 1.09);
  // uniform samples of the same count come far closer (0.03).
  const float r_max = std::sqrt(1.0f / (2.0f * std::sqrt(3.0f) * float(target)));
  std::vector<vec3> free_chosen(chosen.begin() + long(fixed), chosen.end());
  std::printf("closest pair: eliminated %.4f, uniform %.4f, r_max %.4f\n", closestPair(free_chosen),
              closestPair(random), r_max);
  EXPECT_GT(closestPair(free_chosen), 0.8f * r_max);
  EXPECT_LT(closestPair(random), 0.1f * r_max);
}

ivec4 item(int c3rc, int first, int count) {
  return ivec4(c3rc, first, count, std::bit_cast<int>(1.0f));
}

TEST(HybridLevelOfDetail, StridesTakeTheDensityOfProjectingPointsAPixel) {
  C3rcFrame frame;
  frame.pixels = {10, 4};
  // C3RC 0: two items of 1000 points, the probe took every 10th (100 each) and saw 30 and 10 of
  // them project: a fraction 40 / 200 of its 2,000 kept points (400) project. At 8 a pixel over
  // 10 pixels it takes 80 of them: every 5th point.
  frame.items = {item(0, 0, 1000), item(0, 1000, 1000), item(1, 2000, 64), item(1, 2064, 500)};
  for (int k = 0; k < 2; ++k) frame.items[size_t(k)].w = std::bit_cast<int>(10.0f);
  // C3RC 1: an item the probe took whole (64 points) without a projection is dropped; the other,
  // taken every 5th (100 points) with none seen, is kept at half a point's fraction.
  frame.items[3].w = std::bit_cast<int>(5.0f);
  const std::vector<uint32_t> seen = {30, 10, 0, 0};
  restrideByProjections(frame, seen, 8.0f);
  ASSERT_EQ(frame.items.size(), 3u);
  EXPECT_FLOAT_EQ(std::bit_cast<float>(frame.items[0].w), 5.0f);
  EXPECT_FLOAT_EQ(std::bit_cast<float>(frame.items[1].w), 5.0f);
  EXPECT_EQ(frame.items[2].y, 2064);
  // 564 kept x (0.5 / 164 probed) / (8 x 4 pixels) < 1: every point.
  EXPECT_FLOAT_EQ(std::bit_cast<float>(frame.items[2].w), 1.0f);
  EXPECT_EQ(frame.dropped_items, 1);
  EXPECT_EQ(frame.dropped_c3rcs, 0);
  EXPECT_EQ(frame.lod_points, 2 * shading::hybrid_taken_points(1000, 5.0f) + 500);

  // A C3RC whose only item the probe took whole with nothing projecting is left without items.
  C3rcFrame empty;
  empty.pixels = {3};
  empty.items = {item(0, 0, 50)};
  restrideByProjections(empty, std::vector<uint32_t>{0}, 8.0f);
  EXPECT_TRUE(empty.items.empty());
  EXPECT_EQ(empty.dropped_c3rcs, 1);
  EXPECT_EQ(empty.lod_points, 0);
}

}  // namespace
}  // namespace mirage::test
