// The continuous 3-ray camera (C3RC) of the hybrid backward-forward method: the shared projection
// (the coplanarity cubic and the barycentric test of c3rc_shared.h) against a brute-force search
// of the camera's ray fan, the sidedness flag, and continuity across a shared edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "methods/c3rc_cases.h"

namespace mirage {
namespace {

using namespace c3rc_cases;

// ---------------------------------------------------------------------------------------------
// The sweep shared by the brute-force and sidedness tests (computed once).

enum Exclusion {
  kIncluded,
  kNearBoundary,
  kClosePair,
  kIllConditioned,
  kCollapsed,
  kUnresolved,
  kExclusions
};
const char* const kExclusionNames[kExclusions] = {
    "included", "near a boundary", "close pair", "ill-conditioned", "collapsed", "unresolved"};

struct Case {
  Family family = kDivergent;
  bool on_fan = false;  // q = v(w) + λ d(w) for an interior w: at least one projection
  C3rcData camera{};
  vec3 q{};
  std::vector<Projection> analytic;
  BruteForce brute;
  Exclusion exclusion = kIncluded;
  bool first_only_consistent = true;
};

Exclusion classify(const Fan& f, const Case& c) {
  if (c.brute.unresolved) return kUnresolved;
  bool boundary = c.brute.near_boundary;
  for (const Projection& p : c.analytic) boundary = boundary || p.lowest() < kBoundary;
  if (boundary) return kNearBoundary;
  const double close = 5.0 / kGrid;  // a few grid cells: one local minimum may serve both
  for (const std::vector<Projection>* set : {&c.analytic, &c.brute.projections}) {
    for (size_t a = 0; a < set->size(); ++a) {
      if (conditioning(f, (*set)[a]) < kConditioningMin) return kIllConditioned;
      if (sweptSize(f, (*set)[a].lambda) < kCollapseMin * f.size) return kCollapsed;
      for (size_t b = a + 1; b < set->size(); ++b) {
        double dw = 0.0;
        for (size_t k = 0; k < 3; ++k) dw = std::max(dw, std::abs((*set)[a].w[k] - (*set)[b].w[k]));
        if (dw < close) return kClosePair;
      }
    }
  }
  return kIncluded;
}

struct Sweep {
  std::vector<Case> cases;
  double seconds = 0.0;
};

const Sweep& sweep() {
  static const Sweep result = [] {
    constexpr int kCamerasPerFamily = 160, kPointsPerCamera = 6;  // half on the fan, half in a box
    Sweep s;
    auto start = std::chrono::steady_clock::now();
    Rng rng(20240611);
    for (int family = 0; family < kFamilies; ++family) {
      for (int cam = 0; cam < kCamerasPerFamily; ++cam) {
        const Triangle t = randomTriangle(rng);
        const Rays rays = familyRays(Family(family), t, rng);
        const auto& d = rays.d;
        const C3rcData camera = cameraOf(t, d);
        const Fan fan = fanOf(camera);
        vec3 lo(kInfinity), hi(-kInfinity);
        for (size_t k = 0; k < 3; ++k)
          for (float l : {0.0f, rays.depth}) {
            lo = glm::min(lo, t.v[k] + l * d[k]);
            hi = glm::max(hi, t.v[k] + l * d[k]);
          }
        const vec3 extent = hi - lo;
        const vec3 margin(0.15f * std::max({extent.x, extent.y, extent.z}));
        lo -= margin;
        hi += margin;
        for (int point = 0; point < kPointsPerCamera; ++point) {
          Case c;
          c.family = Family(family);
          c.camera = camera;
          c.on_fan = point % 2 == 0;
          if (c.on_fan) {
            vec3 w = randomBarycentrics(rng, 0.05f);
            float lambda = uniformIn(rng, 0.0f, rays.depth);
            c.q = vec3(fanPoint(fan, {double(w.x), double(w.y), double(w.z)}, double(lambda)));
          } else {
            c.q = vec3(uniformIn(rng, lo.x, hi.x), uniformIn(rng, lo.y, hi.y),
                       uniformIn(rng, lo.z, hi.z));
          }
          c.analytic = analyticProjections(camera, c.q);
          c.brute = bruteForce(fan, dvec3(c.q));
          c.exclusion = classify(fan, c);
          vec4 p[3];
          int first = shading::c3rc_project(camera, c.q, kEps, true, p[0], p[1], p[2]);
          c.first_only_consistent = first == std::min<int>(1, int(c.analytic.size())) &&
                                    (first == 0 || (double(p[0].w) == c.analytic[0].lambda &&
                                                    double(p[0].x) == c.analytic[0].w[0]));
          s.cases.push_back(c);
        }
      }
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
  }();
  return result;
}

// How the analytic projections matched their brute-force roots.
struct MatchTally {
  int projections = 0, within_fixed = 0;
  double worst = 0.0, worst_ratio = 0.0;  // the largest distance, and of its tolerance
};

// Each analytic projection of case `c` against its nearest unused brute-force root.
void matchBruteForce(const Case& c, const Fan& fan, MatchTally& t) {
  // The same projections. The brute-force roots are exact (double, residual < 1e-10); the
  // shared code is float, and its projection misses q by its residual r (≤ 1e-4 · scale,
  // checked by the caller), which moves (w0, w1, λ) by about |J⁻¹| r (J the fan's Jacobian there,
  // large near a fold: up to ~400 per unit here). So each analytic projection must lie within
  // kMatchTolerance + 2 |J⁻¹| r of its own brute-force root (barycentrics absolutely, λ
  // relative beyond λ = 1): the same root, as precise as its residual allows, and never
  // another projection of q, which is at least 5 grid cells (2e-2) away.
  std::vector<bool> used(c.brute.projections.size(), false);
  for (const Projection& p : c.analytic) {
    size_t best = 0;
    double best_e = kInfinity;
    for (size_t b = 0; b < c.brute.projections.size(); ++b) {
      double e = projectionDistance(p, c.brute.projections[b]);
      if (!used[b] && e < best_e) {
        best_e = e;
        best = b;
      }
    }
    used[best] = true;
    const Projection& b = c.brute.projections[best];
    const double residual = glm::length(fanPoint(fan, p.w, p.lambda) - dvec3(c.q));
    const double spread = frobenius(glm::inverse(fanJacobian(fan, b)));
    const double tolerance = kMatchTolerance + 2.0 * spread * residual;
    t.worst = std::max(t.worst, best_e);
    ++t.projections;
    t.within_fixed += best_e <= 1e-4;
    t.worst_ratio = std::max(t.worst_ratio, best_e / tolerance);
    EXPECT_LE(best_e, tolerance) << kFamilyNames[c.family] << " λ " << p.lambda << " vs "
                                 << b.lambda << " conditioning " << conditioning(fan, b)
                                 << " residual " << residual << " |J^-1| " << spread;
  }
}

TEST(C3rcProject, MatchesBruteForceSearchOfTheRayFan) {
  const Sweep& s = sweep();
  int counts[kFamilies][4] = {}, excluded_in[kFamilies] = {};
  int exclusions[kExclusions] = {};
  MatchTally match;
  double worst_exact = 0.0, worst_exact_excluded = 0.0;
  int compared = 0;
  for (const Case& c : s.cases) {
    ++exclusions[c.exclusion];
    EXPECT_TRUE(c.first_only_consistent) << "first_only must return the first of the full list";
    ASSERT_LE(c.analytic.size(), 3u);
    ASSERT_LE(c.brute.projections.size(), 3u);
    // Every analytic projection is exact: its ray passes through q.
    const Fan fan = fanOf(c.camera);
    const double scale = 1.0 + glm::length(dvec3(c.q));
    for (size_t i = 0; i < c.analytic.size(); ++i) {
      const Projection& p = c.analytic[i];
      EXPECT_GE(p.lambda, 0.0);
      EXPECT_LE(p.lambda, fan.lambda_max);
      if (i > 0) {
        EXPECT_GE(p.lambda, c.analytic[i - 1].lambda) << "ascending λ";
      }
      double miss = glm::length(fanPoint(fan, p.w, p.lambda) - dvec3(c.q)) / scale;
      if (c.exclusion == kIncluded) {
        worst_exact = std::max(worst_exact, miss);
        EXPECT_LE(miss, kExactTolerance) << kFamilyNames[c.family] << " λ " << p.lambda;
      } else {
        worst_exact_excluded = std::max(worst_exact_excluded, miss);
      }
    }
    if (c.exclusion != kIncluded) {
      ++excluded_in[c.family];
      continue;
    }
    ++compared;
    ++counts[c.family][c.analytic.size()];
    if (c.on_fan) {
      EXPECT_GE(c.analytic.size(), 1u) << "a point on the fan has a projection";
    }
    ASSERT_EQ(c.analytic.size(), c.brute.projections.size())
        << kFamilyNames[c.family] << (c.on_fan ? " fan" : " box") << " point (" << c.q.x << ", "
        << c.q.y << ", " << c.q.z << ")";
    matchBruteForce(c, fan, match);
  }
  int excluded = int(s.cases.size()) - exclusions[kIncluded];
  std::printf("C3RC sweep: %zu cases (%.2f s), %d compared, %d excluded (%.2f%%):", s.cases.size(),
              s.seconds, compared, excluded, 100.0 * excluded / double(s.cases.size()));
  for (int e = 1; e < kExclusions; ++e) std::printf(" %s %d,", kExclusionNames[e], exclusions[e]);
  std::printf(
      "\n  %d projections matched, %d within 1e-4; worst %.2e (%.2f of its tolerance); "
      "worst exactness %.2e (excluded cases %.2e)\n",
      match.projections, match.within_fixed, match.worst, match.worst_ratio, worst_exact,
      worst_exact_excluded);
  for (int f = 0; f < kFamilies; ++f)
    std::printf("  %-10s projections 0/1/2/3: %d/%d/%d/%d, %d excluded\n", kFamilyNames[f],
                counts[f][0], counts[f][1], counts[f][2], counts[f][3], excluded_in[f]);
  RecordProperty("cases", int(s.cases.size()));
  RecordProperty("excluded", excluded);
  RecordProperty("convergent_double", counts[kConvergent][2]);
  RecordProperty("convergent_triple", counts[kConvergent][3]);
  EXPECT_LT(excluded, int(0.05 * double(s.cases.size()))) << "too many ambiguous cases";
  // The sweep must exercise multiple projections, triple ones included.
  EXPECT_GE(counts[kConvergent][2], 20);
  EXPECT_GE(counts[kConvergent][3], 3);
}

TEST(C3rcSidedness, DivergentNeverProjectsTwiceAndMultipleProjectionsAreFlagged) {
  const Sweep& s = sweep();
  int divergent = 0, multiple = 0, flagged = 0;
  for (const Case& c : s.cases) {
    const bool flag = (int(c.camera.info.z) & MIRAGE_C3RC_MULTIPLE) != 0;
    flagged += flag;
    const size_t most =
        std::max(c.analytic.size(), c.brute.unresolved ? 0 : c.brute.projections.size());
    if (c.family == kDivergent) {
      ++divergent;
      EXPECT_FALSE(flag) << "a divergent C3RC keeps its rays on one side";
      EXPECT_LE(c.analytic.size(), 1u);
      EXPECT_LE(c.brute.projections.size(), 1u);
    }
    if (!flag) {
      // The rays on one side everywhere: the swept triangle never folds.
      EXPECT_LE(c.analytic.size(), 1u) << kFamilyNames[c.family];
      if (!c.brute.unresolved) {
        EXPECT_LE(c.brute.projections.size(), 1u) << kFamilyNames[c.family];
      }
    }
    if (most < 2) continue;
    ++multiple;
    EXPECT_TRUE(flag) << kFamilyNames[c.family] << ": " << most << " projections, no flag";
    // Between two projections of one point the swept triangle has folded: some λ between them
    // has the rays on both sides, so the mixed interval info.xy reaches into [λa, λb].
    for (const std::vector<Projection>* set : {&c.analytic, &c.brute.projections}) {
      for (size_t i = 0; i + 1 < set->size(); ++i) {
        double la = (*set)[i].lambda, lb = (*set)[i + 1].lambda;
        EXPECT_LE(double(c.camera.info.x), lb + 1e-4) << "mixed interval after both projections";
        EXPECT_GE(double(c.camera.info.y), la - 1e-4) << "mixed interval before both projections";
      }
    }
  }
  std::printf("sidedness: %d divergent cases, %d cases with multiple projections, %d flagged\n",
              divergent, multiple, flagged);
  EXPECT_GT(multiple, 0);
}

// ---------------------------------------------------------------------------------------------
// Neighbouring C3RCs.

// Two C3RCs sharing the edge v0 v1 and its construction rays, the third vertices on opposite
// sides (neighbouring reflector triangles, folded by up to ~20°): a = (v0, v1, v2), b = (v1, v0,
// v3). The rays come from one ray field over the four vertices, as on a reflector mesh.
struct EdgePair {
  C3rcData a{}, b{};
  float depth = 3.0f;
};

EdgePair randomEdgePair(Family family, Rng& rng) {
  const Triangle t = randomTriangle(rng);
  const vec3 n = t.normal(), e = glm::normalize(t.v[1] - t.v[0]);
  const vec3 foot = t.v[0] + e * glm::dot(t.v[2] - t.v[0], e), out = t.v[2] - foot;
  const vec3 v3 = foot - out * uniformIn(rng, 0.6f, 1.4f) +
                  e * glm::length(t.v[1] - t.v[0]) * uniformIn(rng, -0.3f, 0.3f) -
                  n * glm::length(out) * uniformIn(rng, 0.0f, 0.35f);
  const std::array<vec3, 4> v = {t.v[0], t.v[1], t.v[2], v3};
  const vec3 c = 0.25f * (v[0] + v[1] + v[2] + v[3]);
  const float longest = std::max({t.longest(), glm::length(v3 - v[0]), glm::length(v3 - v[1])});
  std::array<vec3, 4> d{};
  EdgePair pair;
  if (family == kDivergent) {
    vec3 common = randomInCone(rng, n, radians(40.0f));
    float spread = uniformIn(rng, 0.3f, 2.0f);
    for (size_t k = 0; k < 4; ++k) d[k] = glm::normalize(common + spread * (v[k] - c));
  } else if (family == kConvergent) {
    vec3 focus = c + n * longest * uniformIn(rng, 0.15f, 0.5f) +
                 randomUnit(rng) * longest * uniformIn(rng, 0.0f, 0.3f);
    for (size_t k = 0; k < 4; ++k)
      d[k] = glm::normalize(focus + randomUnit(rng) * longest * uniformIn(rng, 0.0f, 0.6f) - v[k]);
    pair.depth = 4.0f * glm::length(focus - c);
  } else {
    for (size_t k = 0; k < 4; ++k) d[k] = randomInCone(rng, n, radians(60.0f));
  }
  pair.a = makeC3rc(v[0], v[1], v[2], d[0], d[1], d[2], kLambdaMax);
  pair.b = makeC3rc(v[1], v[0], v[3], d[1], d[0], d[3], kLambdaMax);
  return pair;
}

// The projection of `list` nearest `expected` (and how near), or none.
const Projection* nearest(const std::vector<Projection>& list, const Projection& expected,
                          double& distance) {
  const Projection* best = nullptr;
  distance = kInfinity;
  for (const Projection& p : list) {
    double e = projectionDistance(p, expected);
    if (e < distance) {
      distance = e;
      best = &p;
    }
  }
  return best;
}

TEST(C3rcEdge, NeighboursProjectTheSharedEdgeAlikeAndNothingTwice) {
  Rng rng(7031);
  int edge_points = 0, skipped = 0, side_points = 0, near_fold = 0, single_sided = 0;
  double worst_base = 0.0, worst_lambda = 0.0;
  for (int p = 0; p < 240; ++p) {
    const Family family = Family(p % kFamilies);
    const EdgePair pair = randomEdgePair(family, rng);
    const Fan fa = fanOf(pair.a), fb = fanOf(pair.b);
    for (int i = 0; i < 12; ++i) {
      const double t = uniformIn(rng, 0.05f, 0.95f), lambda = uniformIn(rng, 0.0f, pair.depth);
      const Projection in_a{{1.0 - t, t, 0.0}, lambda}, in_b{{t, 1.0 - t, 0.0}, lambda};
      const vec3 q(fanPoint(fa, in_a.w, lambda));
      // A point on the shared wall; skipped where either camera cannot pin it down (a caustic,
      // a focus, λ ≈ 0), as in the sweep.
      const double cond = std::min(conditioning(fa, in_a), conditioning(fb, in_b));
      if (lambda < kBoundary || cond < kConditioningMin ||
          sweptSize(fa, lambda) < kCollapseMin * fa.size ||
          sweptSize(fb, lambda) < kCollapseMin * fb.size) {
        ++skipped;
        continue;
      }
      ++edge_points;
      double ea = 0.0, eb = 0.0;
      // With the shader's slack: w2 = 0 on the shared wall comes out as ±1e-5 or so in float.
      const auto pa = analyticProjections(pair.a, q, kShaderEps);
      const auto pb = analyticProjections(pair.b, q, kShaderEps);
      const Projection* a = nearest(pa, in_a, ea);
      const Projection* b = nearest(pb, in_b, eb);
      const bool seen_a = a && ea < 1e-3, seen_b = b && eb < 1e-3;
      // No crack: at least one of the two sees it.
      EXPECT_TRUE(seen_a || seen_b) << kFamilyNames[family] << " edge point lost by both";
      // Both, alike, unless the point is near a fold: there the float cubic's root moves w2 by
      // ~|J⁻¹| · 1e-5 (up to 3e-4 seen at conditioning 0.027), beyond the slack.
      if (cond < 0.1) {
        ++near_fold;
        single_sided += seen_a != seen_b;
        continue;
      }
      ASSERT_TRUE(seen_a && seen_b) << kFamilyNames[family] << " edge point missed";
      const double scale = 1.0 + glm::length(dvec3(q));
      const double base = glm::length(fanPoint(fa, a->w, 0.0) - fanPoint(fb, b->w, 0.0)) / scale;
      const double dl = std::abs(a->lambda - b->lambda) / std::max(1.0, lambda);
      worst_base = std::max(worst_base, base);
      worst_lambda = std::max(worst_lambda, dl);
      EXPECT_LE(base, 1e-4) << kFamilyNames[family] << ": the same reflector point";
      EXPECT_LE(dl, 1e-4) << kFamilyNames[family] << ": the same λ";
      if (family != kDivergent || lambda < 0.05) continue;
      // Just off the edge (2 % into one triangle): divergent neighbours do not overlap, so
      // exactly one of them projects it, once.
      constexpr double kInside = 0.02;
      for (int side = 0; side < 2; ++side) {
        const Fan& own = side == 0 ? fa : fb;
        const C3rcData& mine = side == 0 ? pair.a : pair.b;
        const C3rcData& other = side == 0 ? pair.b : pair.a;
        const Projection& edge = side == 0 ? in_a : in_b;
        const Projection expected{
            {edge.w[0] * (1.0 - kInside), edge.w[1] * (1.0 - kInside), kInside}, lambda};
        const vec3 qs(fanPoint(own, expected.w, lambda));
        const auto mp = analyticProjections(mine, qs), op = analyticProjections(other, qs);
        ++side_points;
        ASSERT_EQ(mp.size(), 1u) << "the own triangle projects it once";
        EXPECT_LT(projectionDistance(mp[0], expected), 1e-3);
        EXPECT_EQ(op.size(), 0u) << "the neighbour does not project it";
      }
    }
  }
  std::printf(
      "shared edges: %d edge points (%d skipped as ambiguous; %d near a fold, %d of them "
      "seen by one neighbour only), %d side points; worst base point gap %.2e, worst λ "
      "gap %.2e\n",
      edge_points, skipped, near_fold, single_sided, side_points, worst_base, worst_lambda);
  EXPECT_LT(skipped, edge_points / 10);
}

}  // namespace
}  // namespace mirage
