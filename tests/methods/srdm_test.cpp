// Simplified rotated depth maps on the CPU: row simplification (the impostor paper, §4.2), the
// builder, and the shared ray-SRDM intersection (§4.3) against brute-force marching of the full
// depth map.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "methods/depthmap/srdm.h"
#include "methods/depthmap/srdm_shared.h"
#include "support/depth_maps.h"

namespace mirage {
namespace {

DepthMap testMap(int size = 128) {
  return test::threeSpheresDepthMap(size);
}

RowSamples syntheticRow(const std::vector<float>& d) {
  RowSamples row;
  row.spacing = 1.0f;
  row.d = d;
  for (size_t k = 0; k < d.size(); ++k) row.s.push_back(float(k) + 0.5f);
  return row;
}

// A span of samples 3..20 in a row of 26, piecewise linear between `vertices` (sample indices,
// the span's two end samples first and last) with depths 0.5, 0.2, 0.35, 0.3, 0.45 in turn.
std::vector<float> piecewiseLinearSpan(const std::vector<int>& vertices) {
  const float depths[] = {0.5f, 0.2f, 0.35f, 0.3f, 0.45f};
  std::vector<float> d(26, 1.0f);
  for (int k = vertices.front(); k <= vertices.back(); ++k) {
    size_t seg = 0;
    while (seg + 2 < vertices.size() && k > vertices[seg + 1]) ++seg;
    const float u = float(k - vertices[seg]) / float(vertices[seg + 1] - vertices[seg]);
    d[size_t(k)] = depths[seg] + (depths[seg + 1] - depths[seg]) * u;
  }
  return d;
}

TEST(SrdmRow, ExactForPiecewiseLinearSpansWithAtMostMMinusTwoVertices) {
  // The span's end points sit half a sample outside it with its end samples' depths: a sloped
  // end segment needs a knot on its end sample too. Greedy's worst sample is always a vertex
  // (the error is linear between vertices), so with V vertices (the end samples counted) it is
  // exact from m = V + 2 points and not at m = V + 1. The fit refits greedy's knots, exact
  // whenever greedy's are.
  DepthMap map;
  map.near = 1.0f;
  map.far = 5.0f;
  for (const std::vector<int>& vertices :
       std::vector<std::vector<int>>{{3, 20}, {3, 11, 20}, {3, 9, 14, 20}, {3, 7, 11, 15, 20}}) {
    const std::vector<float> d = piecewiseLinearSpan(vertices);
    const RowSamples row = syntheticRow(d);
    const int v = int(vertices.size());
    auto worst = [&](int m, SrdmSimplifier simplifier) {
      RowPolyline poly;
      simplifyRow(map, row, m, simplifier, poly);
      EXPECT_LE(int(poly.points.size()), m);
      EXPECT_LT(evaluateRow(poly, row.s[1]), 0.0f) << "background before the span";
      EXPECT_LT(evaluateRow(poly, row.s[23]), 0.0f) << "background after the span";
      float e = 0.0f;
      for (int k = vertices.front(); k <= vertices.back(); ++k)
        e = std::max(e, std::abs(evaluateRow(poly, row.s[size_t(k)]) - d[size_t(k)]));
      return e;
    };
    for (SrdmSimplifier simplifier : {SrdmSimplifier::kGreedy, SrdmSimplifier::kFit})
      EXPECT_LT(worst(v + 2, simplifier), 1e-5f)
          << srdmSimplifierName(simplifier) << ", " << v << " vertices, m = " << v + 2;
    // Measured: 3.9e-3 to 1.4e-2 (an end sample off its true depth).
    EXPECT_GT(worst(v + 1, SrdmSimplifier::kGreedy), 1e-3f)
        << "greedy, " << v << " vertices, m = " << v + 1;
  }
}

TEST(SrdmRow, GapsAreNeverBridgedAndExtraSpansDropTheShortest) {
  // Four spans of lengths 3, 1, 5, 2 with m = 6: room for three; the single sample goes.
  std::vector<float> d(20, 1.0f);
  for (int k : {1, 2, 3, 6, 9, 10, 11, 12, 13, 16, 17}) d[size_t(k)] = 0.4f;
  DepthMap map;
  RowPolyline poly;
  simplifyRow(map, syntheticRow(d), 6, SrdmSimplifier::kGreedy, poly);
  EXPECT_EQ(poly.points.size(), 6u);
  EXPECT_EQ(poly.dropped, 1);
  EXPECT_LT(evaluateRow(poly, 6.5f), 0.0f) << "the dropped sliver";
  EXPECT_LT(evaluateRow(poly, 4.5f), 0.0f) << "a gap";
  EXPECT_LT(evaluateRow(poly, 14.5f), 0.0f) << "a gap";
  EXPECT_NEAR(evaluateRow(poly, 11.5f), 0.4f, 1e-6f);
  EXPECT_NEAR(evaluateRow(poly, 17.5f), 0.4f, 1e-6f);
}

TEST(SrdmBuild, AtMostMPointsAndErrorFallsAsMGrows) {
  const DepthMap map = testMap();
  for (SrdmSimplifier simplifier : {SrdmSimplifier::kGreedy, SrdmSimplifier::kFit}) {
    double previous = 1e9;
    for (int m : {4, 8, 16, 32}) {
      const Srdm srdm = buildSrdm(map, {30, m, simplifier});
      ASSERT_EQ(srdm.texels.size(), size_t(30 * 128 * ((m + 1) / 2)));
      for (int row = 0; row < 128; row += 7)
        EXPECT_LE(decodeRow(srdm, 11, row).points.size(), size_t(m));
      const SrdmError e = measureSrdmError(map, srdm);
      EXPECT_GT(e.samples, 100000);
      EXPECT_LE(e.mean, previous) << srdmSimplifierName(simplifier) << " m = " << m;
      previous = e.mean;
    }
  }
}

TEST(SrdmBuild, TheFitBeatsGreedyOnAverage) {
  const DepthMap map = testMap();
  for (int m : {6, 8, 12, 16}) {
    const double greedy =
        measureSrdmError(map, buildSrdm(map, {30, m, SrdmSimplifier::kGreedy})).mean;
    const double fit = measureSrdmError(map, buildSrdm(map, {30, m, SrdmSimplifier::kFit})).mean;
    std::printf("m = %d: mean relative z error greedy %.4f%%, fit %.4f%%\n", m, 100 * greedy,
                100 * fit);
    EXPECT_LT(fit, greedy) << "m = " << m;
  }
}

TEST(SrdmBuild, RejectsSettingsOutOfRange) {
  const DepthMap map = testMap(32);
  EXPECT_THROW(buildSrdm(map, {0, 8, SrdmSimplifier::kGreedy}), InputError);
  EXPECT_THROW(buildSrdm(map, {60, 1, SrdmSimplifier::kGreedy}), InputError);
  EXPECT_THROW(buildSrdm(map, {60, 33, SrdmSimplifier::kGreedy}), InputError) << "m > w";
  EXPECT_THROW(parseSrdmSimplifier("optimal"), InputError);
}

TEST(SrdmGeometry, DomainsRowsAndTheirInverse) {
  const float w = 256.0f;
  for (int i = 0; i < 60; i += 7) {
    const float theta = shading::srdm_theta(i, 60);
    const vec2 p(37.25f, 201.5f);
    const vec2 st = shading::srdm_to_domain(p, theta, w);
    const vec2 back = shading::srdm_from_domain(st, theta, w);
    EXPECT_NEAR(back.x, p.x, 1e-3f);
    EXPECT_NEAR(back.y, p.y, 1e-3f);
    EXPECT_GE(st.x, 0.0f);
    EXPECT_LE(st.x, shading::srdm_extent(theta, w));
    const int row = shading::srdm_row_of(st.y, theta, 256);
    ASSERT_GE(row, 0);
    EXPECT_LE(std::abs(shading::srdm_row_t(row, theta, 256) - st.y),
              0.5f * shading::srdm_extent(theta, w) / w + 1e-3f);
    // A direction along the domain's rows picks that domain.
    EXPECT_EQ(shading::srdm_domain_of(vec2(std::cos(theta), std::sin(theta)), 60), i);
    EXPECT_EQ(shading::srdm_domain_of(-vec2(std::cos(theta), std::sin(theta)), 60), i);
  }
}

// The brute-force reference: march the full depth map along the projected ray in small steps
// (nearest texel) and take the first step from in front of a foreground texel to behind one.
float marchDepthMap(const DepthMap& map, vec3 from, vec3 to) {
  const float length = glm::length(vec2(to) - vec2(from));
  const int steps = std::max(int(length * 8.0f), 1);
  bool was_in_front = false;
  for (int i = 0; i <= steps; ++i) {
    const float u = float(i) / float(steps);
    const vec3 p = glm::mix(from, to, u);
    const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
    if (x < 0 || y < 0 || x >= map.size || y >= map.size || !DepthMap::isForeground(map.at(x, y))) {
      was_in_front = false;
      continue;
    }
    const bool in_front = p.z < map.at(x, y);
    if (was_in_front && !in_front) return u;
    was_in_front = in_front;
  }
  return -1.0f;
}

// Hit/miss agreement with marching the full map, and the mean relative z difference of the
// rays both hit, over random rays from in front of the three-spheres object to behind it.
struct SearchAgreement {
  double agreement = 0.0, depth_error = 0.0;
  int both_hit = 0;
};

SearchAgreement searchAgainstMarching(const DepthMap& map, const Srdm& srdm, SrdmSearch search) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> xy(0.0f, float(map.size)), near_d(0.0f, 0.6f),
      far_d(0.85f, 1.0f);
  int agree = 0, both_hit = 0;
  const int total = 4000;
  double depth_error = 0.0;
  for (int i = 0; i < total; ++i) {
    const vec3 from(xy(rng), xy(rng), near_d(rng)), to(xy(rng), xy(rng), far_d(rng));
    const float ours = intersectSrdm(srdm, from, to, search);
    const float truth = marchDepthMap(map, from, to);
    agree += (ours >= 0.0f) == (truth >= 0.0f);
    if (ours >= 0.0f && truth >= 0.0f) {
      ++both_hit;
      const float z_ours = map.eyeDepth(glm::mix(from.z, to.z, ours));
      const float z_truth = map.eyeDepth(glm::mix(from.z, to.z, truth));
      depth_error += std::abs(z_ours - z_truth) / z_truth;
    }
  }
  return {double(agree) / total, depth_error / std::max(both_hit, 1), both_hit};
}

TEST(SrdmIntersect, AgreesWithBruteForceMarchingOnRandomRays) {
  const DepthMap map = testMap(128);
  const Srdm srdm = buildSrdm(map, {60, 16, SrdmSimplifier::kGreedy});
  const SearchAgreement r = searchAgainstMarching(map, srdm, SrdmSearch::kOneRow);
  std::printf("hit/miss agreement %.4f, %d hits in both, mean relative z difference %.4f%%\n",
              r.agreement, r.both_hit, 100.0 * r.depth_error);
  EXPECT_GT(r.both_hit, 500);
  EXPECT_GT(r.agreement, 0.95);
  EXPECT_LT(r.depth_error, 0.01);
}

TEST(SrdmIntersect, InterpolatedRowsAlongADomainAreThatDomainsRow) {
  // A projected ray along a domain's angle gives the other domain no weight: the blend of the
  // two rows is the one row's polyline, so the crossing must be the one row's.
  const DepthMap map = testMap(128);
  const int n = 9;
  const Srdm srdm = buildSrdm(map, {n, 16, SrdmSimplifier::kGreedy});
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> xy(20.0f, 108.0f), len(10.0f, 100.0f), d0(0.0f, 0.6f),
      d1(0.85f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const float theta = shading::srdm_theta(i % n, n) + (i % 2 == 0 ? 0.0f : MIRAGE_SRDM_PI);
    const vec2 a(xy(rng), xy(rng));
    const vec2 b = a + len(rng) * vec2(std::cos(theta), std::sin(theta));
    const vec3 from(a, d0(rng)), to(b, d1(rng));
    const float one = intersectSrdm(srdm, from, to, SrdmSearch::kOneRow);
    const float blend = intersectSrdm(srdm, from, to, SrdmSearch::kTwoRowsInterpolated);
    hits += one >= 0.0f;
    ASSERT_EQ(one >= 0.0f, blend >= 0.0f) << "ray " << i;
    if (one >= 0.0f) {
      EXPECT_NEAR(blend, one, 1e-4f) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 200);
}

TEST(SrdmIntersect, InterpolatedRowsFollowTheRayBetweenCoarseDomains) {
  // At n = 9 (20 degrees) one row departs from an oblique ray by up to 10 degrees; the two
  // nearest domains' rows interpolated must agree with marching the full map better, at the
  // midpoint and at the first row's hit.
  const DepthMap map = testMap(128);
  for (int n : {9, 18}) {
    const Srdm srdm = buildSrdm(map, {n, 16, SrdmSimplifier::kGreedy});
    const SearchAgreement one = searchAgainstMarching(map, srdm, SrdmSearch::kOneRow);
    const SearchAgreement hit = searchAgainstMarching(map, srdm, SrdmSearch::kTwoRowsHit);
    const SearchAgreement blend =
        searchAgainstMarching(map, srdm, SrdmSearch::kTwoRowsInterpolated);
    const SearchAgreement hit_blend =
        searchAgainstMarching(map, srdm, SrdmSearch::kHitInterpolated);
    std::printf(
        "n = %d: agreement / mean relative z difference: one row %.4f / %.4f%%, hit row "
        "%.4f / %.4f%%, interpolated %.4f / %.4f%%, interpolated at the hit %.4f / %.4f%%\n",
        n, one.agreement, 100.0 * one.depth_error, hit.agreement, 100.0 * hit.depth_error,
        blend.agreement, 100.0 * blend.depth_error, hit_blend.agreement,
        100.0 * hit_blend.depth_error);
    // Measured (agreement / mean relative z difference): n = 9: one row 0.9805 / 0.504%, hit
    // row 0.9865 / 0.297%, interpolated 0.9848 / 0.377%, interpolated at the hit 0.9868 /
    // 0.285%; n = 18: 0.9875 / 0.395%, 0.9900 / 0.302%, 0.9892 / 0.308%, 0.9900 / 0.280%.
    EXPECT_GE(blend.agreement, one.agreement) << "n = " << n;
    EXPECT_LT(blend.depth_error, one.depth_error) << "n = " << n;
    EXPECT_GE(hit_blend.agreement, one.agreement) << "n = " << n;
    EXPECT_LT(hit_blend.depth_error, hit.depth_error) << "n = " << n;
  }
}

}  // namespace
}  // namespace mirage
