// The continuous 3-ray camera (C3RC) of the hybrid backward-forward method: the shared projection
// (the coplanarity cubic and the barycentric test of c3rc_shared.h) against a brute-force search
// of the camera's ray fan, the sidedness flag, continuity across a shared edge, the reflected-ray
// C3RC of a planar mirror and of a sphere, affine transforms, degenerate input, and the cubic
// root finder. Everything is seeded: the same cases run every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "methods/hybrid/c3rc.h"
#include "methods/hybrid/c3rc_shared.h"

namespace mirage {
namespace {

using glm::dvec3;
using Rng = std::mt19937;

constexpr float kEps = 1e-5f;         // the barycentric slack c3rc_project is called with
constexpr float kShaderEps = 1e-4f;   // the slack of the splatting shader and the culling
constexpr float kLambdaMax = 100.0f;  // far beyond every test point (λ ≤ ~10 there)

float uniformIn(Rng& rng, float lo, float hi) {
  return std::uniform_real_distribution<float>(lo, hi)(rng);
}

vec3 randomUnit(Rng& rng) {
  std::normal_distribution<float> normal(0.0f, 1.0f);
  for (;;) {
    vec3 v(normal(rng), normal(rng), normal(rng));
    float l = glm::length(v);
    if (l > 1e-3f) return v / l;
  }
}

// A unit vector uniformly distributed over the cone of half-angle `angle` around the unit `axis`.
vec3 randomInCone(Rng& rng, const vec3& axis, float angle) {
  float cz = uniformIn(rng, std::cos(angle), 1.0f);
  float sz = std::sqrt(std::max(0.0f, 1.0f - cz * cz));
  float phi = uniformIn(rng, 0.0f, 2.0f * kPi);
  vec3 t = glm::normalize(
      glm::cross(axis, std::abs(axis.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
  vec3 b = glm::cross(axis, t);
  return glm::normalize(cz * axis + sz * (std::cos(phi) * t + std::sin(phi) * b));
}

// Barycentrics with every w_k ≥ lo, uniform over that sub-simplex (rejection from uniform).
vec3 randomBarycentrics(Rng& rng, float lo) {
  for (;;) {
    float a = uniformIn(rng, 0.0f, 1.0f), b = uniformIn(rng, 0.0f, 1.0f);
    if (a > b) std::swap(a, b);
    vec3 w(a, b - a, 1.0f - b);
    if (w.x >= lo && w.y >= lo && w.z >= lo) return w;
  }
}

struct Triangle {
  std::array<vec3, 3> v;
  vec3 normal() const { return glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0])); }
  vec3 centroid() const { return (v[0] + v[1] + v[2]) / 3.0f; }
  float longest() const {
    return std::max({glm::length(v[1] - v[0]), glm::length(v[2] - v[1]), glm::length(v[0] - v[2])});
  }
};

// Edge lengths in [0.1, 1], no slivers (degenerate triangles have their own test).
Triangle randomTriangle(Rng& rng) {
  for (;;) {
    vec3 v0(uniformIn(rng, -0.5f, 0.5f), uniformIn(rng, -0.5f, 0.5f), uniformIn(rng, -0.5f, 0.5f));
    vec3 v1 = v0 + randomUnit(rng) * uniformIn(rng, 0.1f, 1.0f);
    vec3 v2 = v0 + randomUnit(rng) * uniformIn(rng, 0.1f, 1.0f);
    Triangle t{{v0, v1, v2}};
    float e = glm::length(v2 - v1), longest = t.longest();
    if (e < 0.1f || e > 1.0f) continue;
    if (glm::length(glm::cross(v1 - v0, v2 - v0)) < 0.2f * longest * longest) continue;
    return t;
  }
}

enum Family { kDivergent, kConvergent, kRandomRays, kFamilies };
const char* const kFamilyNames[kFamilies] = {"divergent", "convergent", "random"};

// Unit construction rays of one family for the triangle, and the depth (the largest λ) of the
// region worth probing: where the family's projections are interesting.
struct Rays {
  std::array<vec3, 3> d{};
  float depth = 3.0f;
};

Rays familyRays(Family family, const Triangle& t, Rng& rng) {
  const vec3 n = t.normal(), c = t.centroid();
  const float longest = t.longest();
  Rays r;
  switch (family) {
    case kDivergent: {  // a common direction plus an outward spread from the centroid (convex)
      vec3 common = randomInCone(rng, n, radians(40.0f));
      float spread = uniformIn(rng, 0.3f, 2.0f);
      for (size_t k = 0; k < 3; ++k) r.d[k] = glm::normalize(common + spread * (t.v[k] - c));
      break;
    }
    case kConvergent: {
      // Aimed at a blurred focus in front (concave): the rays cross, then spread. The focus is
      // close, 0.15 to 0.5 edge lengths, so the rays are steep: farther foci fold T(λ) so little
      // that 2 or 3 projections are rare and ill-conditioned. Probed to 4 focal distances.
      vec3 focus = c + n * longest * uniformIn(rng, 0.15f, 0.5f) +
                   randomUnit(rng) * longest * uniformIn(rng, 0.0f, 0.3f);
      for (size_t k = 0; k < 3; ++k)
        r.d[k] =
            glm::normalize(focus + randomUnit(rng) * longest * uniformIn(rng, 0.0f, 0.6f) - t.v[k]);
      r.depth = 4.0f * glm::length(focus - c);
      break;
    }
    default:  // anything within 60° of the normal
      for (size_t k = 0; k < 3; ++k) r.d[k] = randomInCone(rng, n, radians(60.0f));
      break;
  }
  return r;
}

C3rcData cameraOf(const Triangle& t, const std::array<vec3, 3>& d) {
  return makeC3rc(t.v[0], t.v[1], t.v[2], d[0], d[1], d[2], kLambdaMax);
}

// A projection: barycentrics and λ, in double whichever side computed it.
struct Projection {
  std::array<double, 3> w{};
  double lambda = 0.0;
  double lowest() const { return std::min({w[0], w[1], w[2], lambda}); }
};

std::vector<Projection> analyticProjections(const C3rcData& c, const vec3& q, float eps = kEps) {
  vec4 p[3];
  int n = shading::c3rc_project(c, q, eps, false, p[0], p[1], p[2]);
  std::vector<Projection> out;
  for (int i = 0; i < n; ++i)
    out.push_back({{double(p[i].x), double(p[i].y), double(p[i].z)}, double(p[i].w)});
  return out;
}

// The camera in double precision: the very floats the shared code sees, widened.
struct Fan {
  std::array<dvec3, 3> v, d;
  double lambda_max = 0.0;
  double size = 0.0;  // the base triangle's longest edge
};

Fan fanOf(const C3rcData& c) {
  Fan f;
  f.v = {dvec3(vec3(c.v0)), dvec3(vec3(c.v1)), dvec3(vec3(c.v2))};
  f.d = {dvec3(vec3(c.d0)), dvec3(vec3(c.d1)), dvec3(vec3(c.d2))};
  f.lambda_max = double(c.info.w);
  f.size = std::max(
      {glm::length(f.v[1] - f.v[0]), glm::length(f.v[2] - f.v[1]), glm::length(f.v[0] - f.v[2])});
  return f;
}

// The point of the fan's ray w at λ: v(w) + λ d(w).
dvec3 fanPoint(const Fan& f, const std::array<double, 3>& w, double lambda) {
  dvec3 p(0.0);
  for (size_t k = 0; k < 3; ++k) p += w[k] * (f.v[k] + lambda * f.d[k]);
  return p;
}

// The longest edge of the swept triangle T(λ).
double sweptSize(const Fan& f, double lambda) {
  dvec3 q[3];
  for (size_t k = 0; k < 3; ++k) q[k] = f.v[k] + lambda * f.d[k];
  return std::max({glm::length(q[1] - q[0]), glm::length(q[2] - q[1]), glm::length(q[0] - q[2])});
}

// The Jacobian of (w0, w1, λ) ↦ v(w) + λ d(w) (w2 = 1 − w0 − w1) at a projection: the edges
// p0 − p2, p1 − p2 of T(λ) (p_k = v_k + λ d_k) and the ray d(w).
glm::dmat3 fanJacobian(const Fan& f, const Projection& p) {
  dvec3 q[3];
  for (size_t k = 0; k < 3; ++k) q[k] = f.v[k] + p.lambda * f.d[k];
  dvec3 dw = p.w[0] * f.d[0] + p.w[1] * f.d[1] + p.w[2] * f.d[2];
  return glm::dmat3(q[0] - q[2], q[1] - q[2], dw);
}

double frobenius(const glm::dmat3& m) {
  double s = 0.0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) s += m[a][b] * m[a][b];
  return std::sqrt(s);
}

// How well a projection is determined, whatever the size of T(λ): the smallest singular value
// (to within √3) of the Jacobian with unitless columns (T(λ)'s edges by its longest edge, the
// ray to unit length). It vanishes at a double root of the cubic, where the ray grazes T(λ) (a
// caustic of the C3RC: the projections on either side merge) and where T(λ) degenerates to a
// segment.
double conditioning(const Fan& f, const Projection& p) {
  glm::dmat3 j = fanJacobian(f, p);
  double s = sweptSize(f, p.lambda), l = glm::length(j[2]);
  if (s == 0.0 || l == 0.0) return 0.0;
  j[0] /= s;
  j[1] /= s;
  j[2] /= l;
  if (glm::determinant(j) == 0.0) return 0.0;
  return 1.0 / frobenius(glm::inverse(j));
}

// Newton's method on v(w) + λ d(w) = q in (w0, w1, λ), w2 = 1 − w0 − w1, halving steps that do
// not reduce the residual. Returns the residual |v(w) + λ d(w) − q| reached.
double newtonOnFan(const Fan& f, const dvec3& q, std::array<double, 3>& x) {
  const dvec3 e0 = f.v[0] - f.v[2], e1 = f.v[1] - f.v[2];
  const dvec3 g0 = f.d[0] - f.d[2], g1 = f.d[1] - f.d[2];
  auto residual = [&](const std::array<double, 3>& y) {
    return f.v[2] + y[0] * e0 + y[1] * e1 + y[2] * (f.d[2] + y[0] * g0 + y[1] * g1) - q;
  };
  dvec3 r = residual(x);
  double rn = glm::length(r);
  const double scale = 1.0 + glm::length(q);
  for (int it = 0; it < 60 && rn > 1e-14 * scale; ++it) {
    dvec3 c0 = e0 + x[2] * g0, c1 = e1 + x[2] * g1, c2 = f.d[2] + x[0] * g0 + x[1] * g1;
    double det = glm::dot(c0, glm::cross(c1, c2));
    if (!(std::abs(det) > 1e-300)) break;
    dvec3 b = -r;  // Cramer's rule for J δ = −r
    std::array<double, 3> step = {glm::dot(b, glm::cross(c1, c2)) / det,
                                  glm::dot(c0, glm::cross(b, c2)) / det,
                                  glm::dot(c0, glm::cross(c1, b)) / det};
    double alpha = 1.0;
    bool improved = false;
    for (int halving = 0; halving < 30 && !improved; ++halving, alpha *= 0.5) {
      std::array<double, 3> y = {x[0] + alpha * step[0], x[1] + alpha * step[1],
                                 x[2] + alpha * step[2]};
      dvec3 ry = residual(y);
      if (glm::length(ry) < rn) {
        x = y;
        r = ry;
        rn = glm::length(ry);
        improved = true;
      }
    }
    if (!improved) break;
  }
  return rn;
}

constexpr int kGrid = 240;          // barycentric grid steps per side of the brute force
constexpr double kBoundary = 0.01;  // projections this close to w_k = 0 or λ = 0 are ambiguous

struct BruteForce {
  std::vector<Projection> projections;  // ascending λ
  bool near_boundary = false;  // a root (in or just outside the domain) within kBoundary of it
  bool unresolved = false;     // a candidate Newton could neither solve nor rule out
};

// The projections of q found without the cubic: the distance f(w) from q to the ray
// {v(w) + λ d(w), 0 ≤ λ ≤ λmax} on a regular barycentric grid of step h = 1/kGrid. Between grid
// neighbours the ray moves by at most h (|p0 − p2| + |p1 − p2|) (p_k = v_k + λ d_k, the edges of
// T(λ)), so the grid point nearest a projection has f below that: every grid local minimum of f
// under 1.5 times the bound seeds Newton's method on the 3×3 system v(w) + λ d(w) = q, and the
// distinct solutions with w ≥ 0 and 0 ≤ λ ≤ λmax are the projections (residual < 1e-10).
BruteForce bruteForce(const Fan& f, const dvec3& q) {
  const int n = kGrid;
  const double h = 1.0 / n;
  const size_t stride = size_t(n + 1);
  static std::vector<double> fval, tval;  // reused: the sweep calls this thousands of times
  fval.assign(stride * stride, std::numeric_limits<double>::infinity());
  tval.assign(stride * stride, 0.0);
  const dvec3 e0 = f.v[0] - f.v[2], e1 = f.v[1] - f.v[2];
  const dvec3 g0 = f.d[0] - f.d[2], g1 = f.d[1] - f.d[2];
  // Plain doubles in the hot loop: fast in unoptimised builds too.
  const double vx = f.v[2].x, vy = f.v[2].y, vz = f.v[2].z;
  const double dx = f.d[2].x, dy = f.d[2].y, dz = f.d[2].z;
  for (int i = 0; i <= n; ++i) {
    const double w0 = i * h;
    const double bx = vx + w0 * e0.x, by = vy + w0 * e0.y, bz = vz + w0 * e0.z;
    const double cx = dx + w0 * g0.x, cy = dy + w0 * g0.y, cz = dz + w0 * g0.z;
    for (int j = 0; i + j <= n; ++j) {
      const double w1 = j * h;
      const double rx = q.x - (bx + w1 * e1.x), ry = q.y - (by + w1 * e1.y),
                   rz = q.z - (bz + w1 * e1.z);
      const double sx = cx + w1 * g1.x, sy = cy + w1 * g1.y, sz = cz + w1 * g1.z;
      const double ss = sx * sx + sy * sy + sz * sz;
      double t = ss > 0.0 ? (rx * sx + ry * sy + rz * sz) / ss : 0.0;
      t = std::min(std::max(t, 0.0), f.lambda_max);
      const double ex = rx - t * sx, ey = ry - t * sy, ez = rz - t * sz;
      fval[size_t(i) * stride + size_t(j)] = std::sqrt(ex * ex + ey * ey + ez * ez);
      tval[size_t(i) * stride + size_t(j)] = t;
    }
  }
  static constexpr int kNeighbours[6][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1}};
  std::vector<Projection> roots;
  BruteForce out;
  const double scale = 1.0 + glm::length(q);
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double fij = fval[size_t(i) * stride + size_t(j)];
      bool minimum = true;
      for (const auto& nb : kNeighbours) {
        int a = i + nb[0], b = j + nb[1];
        if (a < 0 || b < 0 || a + b > n) continue;
        if (fval[size_t(a) * stride + size_t(b)] < fij) minimum = false;
      }
      if (!minimum) continue;
      const double t = tval[size_t(i) * stride + size_t(j)];
      const double bound = h * (glm::length(e0 + t * g0) + glm::length(e1 + t * g1));
      if (fij > 1.5 * bound + 1e-12) continue;
      std::array<double, 3> x = {i * h, j * h, t};
      double residual = newtonOnFan(f, q, x);
      if (residual > 1e-10 * scale) {
        if (residual < 1e-6 * scale) out.unresolved = true;  // stalled next to a root
        continue;
      }
      Projection p{{x[0], x[1], 1.0 - x[0] - x[1]}, x[2]};
      bool seen = false;
      for (const Projection& r : roots)
        seen = seen || (std::abs(r.w[0] - p.w[0]) < 1e-7 && std::abs(r.w[1] - p.w[1]) < 1e-7 &&
                        std::abs(r.lambda - p.lambda) < 1e-7 * (1.0 + p.lambda));
      if (!seen) roots.push_back(p);
    }
  }
  for (const Projection& r : roots) {
    double lowest = r.lowest();
    if (lowest > -kBoundary && lowest < kBoundary) out.near_boundary = true;
    if (lowest >= 0.0 && r.lambda <= f.lambda_max) out.projections.push_back(r);
  }
  std::sort(out.projections.begin(), out.projections.end(),
            [](const Projection& a, const Projection& b) { return a.lambda < b.lambda; });
  return out;
}

// The difference of two projections: barycentrics absolute, λ relative beyond 1.
double projectionDistance(const Projection& a, const Projection& b) {
  double e = std::abs(a.lambda - b.lambda) / std::max(1.0, std::abs(b.lambda));
  for (size_t k = 0; k < 3; ++k) e = std::max(e, std::abs(a.w[k] - b.w[k]));
  return e;
}

// ---------------------------------------------------------------------------------------------
// The sweep shared by the brute-force and sidedness tests (computed once).

constexpr double kConditioningMin = 0.02;  // below: a near-double root or a collapsed T(λ)
constexpr double kMatchTolerance = 1e-5;   // see MatchesBruteForce
constexpr double kExactTolerance = 1e-4;   // |v(w) + λ d(w) − Q| per unit of scene size

constexpr double kCollapseMin = 0.05;  // T(λ) smaller than this times the base: a focus

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

TEST(C3rcProject, MatchesBruteForceSearchOfTheRayFan) {
  const Sweep& s = sweep();
  int counts[kFamilies][4] = {}, excluded_in[kFamilies] = {};
  int exclusions[kExclusions] = {};
  int projections = 0, within_fixed = 0;
  double worst_match = 0.0, worst_match_ratio = 0.0, worst_exact = 0.0, worst_exact_excluded = 0.0;
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
    // The same projections. The brute-force roots are exact (double, residual < 1e-10); the
    // shared code is float, and its projection misses q by its residual r (≤ 1e-4 · scale,
    // checked above), which moves (w0, w1, λ) by about |J⁻¹| r (J the fan's Jacobian there,
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
      worst_match = std::max(worst_match, best_e);
      ++projections;
      within_fixed += best_e <= 1e-4;
      worst_match_ratio = std::max(worst_match_ratio, best_e / tolerance);
      EXPECT_LE(best_e, tolerance)
          << kFamilyNames[c.family] << " λ " << p.lambda << " vs " << b.lambda << " conditioning "
          << conditioning(fan, b) << " residual " << residual << " |J^-1| " << spread;
    }
  }
  int excluded = int(s.cases.size()) - exclusions[kIncluded];
  std::printf("C3RC sweep: %zu cases (%.2f s), %d compared, %d excluded (%.2f%%):", s.cases.size(),
              s.seconds, compared, excluded, 100.0 * excluded / double(s.cases.size()));
  for (int e = 1; e < kExclusions; ++e) std::printf(" %s %d,", kExclusionNames[e], exclusions[e]);
  std::printf(
      "\n  %d projections matched, %d within 1e-4; worst %.2e (%.2f of its tolerance); "
      "worst exactness %.2e (excluded cases %.2e)\n",
      projections, within_fixed, worst_match, worst_match_ratio, worst_exact, worst_exact_excluded);
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

// ---------------------------------------------------------------------------------------------
// The reflected-ray C3RC.

vec3 tangentOf(const vec3& n) {
  return glm::normalize(
      glm::cross(n, std::abs(n.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
}

// The distance from p to the line through a and b.
double distanceToLine(const dvec3& p, const dvec3& a, const dvec3& b) {
  return glm::length(glm::cross(p - a, glm::normalize(b - a)));
}

TEST(C3rcReflector, PlanarMirrorIsThePinholeAtTheMirroredEye) {
  // On a plane mirror every reflected ray comes from E', the eye mirrored in the plane: the C3RC
  // must be the pinhole camera at E' (exactly, for any triangle), the reflector point that sees
  // Q the intersection of E'Q with the triangle.
  Rng rng(1303);
  int points = 0, inside = 0, outside = 0;
  double worst = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const vec3 normal = randomUnit(rng), tx = tangentOf(normal), ty = glm::cross(normal, tx);
    const vec3 origin(uniformIn(rng, -1.0f, 1.0f), uniformIn(rng, -1.0f, 1.0f),
                      uniformIn(rng, -1.0f, 1.0f));
    const float size = trial % 4 == 0 ? uniformIn(rng, 1.0f, 4.0f) : uniformIn(rng, 0.05f, 1.0f);
    const vec3 eye = origin + normal * uniformIn(rng, 0.5f, 4.0f) +
                     (tx * uniformIn(rng, -2.0f, 2.0f) + ty * uniformIn(rng, -2.0f, 2.0f)) * size;
    vec3 v[3], n[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = origin + size * (tx * uniformIn(rng, -1.0f, 1.0f) + ty * uniformIn(rng, -1.0f, 1.0f));
      n[k] = trial % 2 == 0 ? normal : -normal;  // seen from behind: facing_normal turns it
    }
    if (glm::length(glm::cross(v[1] - v[0], v[2] - v[0])) < 0.1f * size * size) continue;
    const C3rcData c = reflectorC3rc(eye, v, n, 10.0f);
    EXPECT_FALSE(int(c.info.z) & MIRAGE_C3RC_MULTIPLE) << "a pinhole never projects twice";
    const dvec3 mirrored =
        dvec3(eye) - 2.0 * dvec3(normal) * double(glm::dot(eye - origin, normal));
    const Fan fan = fanOf(c);
    for (size_t k = 0; k < 3; ++k)  // the construction rays come from E'
      EXPECT_LT(distanceToLine(fan.v[k] + fan.d[k], mirrored, fan.v[k]), 1e-5 * (1.0 + size));
    for (int i = 0; i < 20; ++i) {
      // Half the points through the triangle's interior, half anywhere in front of the mirror.
      dvec3 q;
      if (i % 2 == 0) {
        const vec3 w = randomBarycentrics(rng, 0.02f);
        const dvec3 base = fanPoint(fan, {double(w.x), double(w.y), double(w.z)}, 0.0);
        q = base + glm::normalize(base - mirrored) * double(uniformIn(rng, 0.05f, 3.0f));
      } else {
        q = dvec3(origin + normal * uniformIn(rng, 0.05f, 3.0f) +
                  (tx * uniformIn(rng, -2.0f, 2.0f) + ty * uniformIn(rng, -2.0f, 2.0f)) * size);
      }
      q = dvec3(vec3(q));
      // The exact reflection point: E'Q meets the plane, at barycentrics `exact`.
      const dvec3 nn = glm::cross(fan.v[1] - fan.v[0], fan.v[2] - fan.v[0]);
      const double s = glm::dot(fan.v[0] - mirrored, nn) / glm::dot(q - mirrored, nn);
      const dvec3 hit = mirrored + s * (q - mirrored);
      const double area = glm::dot(nn, nn);
      const std::array<double, 3> exact = {
          glm::dot(glm::cross(fan.v[1] - hit, fan.v[2] - hit), nn) / area,
          glm::dot(glm::cross(fan.v[2] - hit, fan.v[0] - hit), nn) / area,
          glm::dot(glm::cross(fan.v[0] - hit, fan.v[1] - hit), nn) / area};
      const double lowest = std::min({exact[0], exact[1], exact[2]});
      if (std::abs(lowest) < kBoundary || s > 1.0 - 1e-3) continue;  // an edge; Q on the mirror
      const auto proj = analyticProjections(c, vec3(q));
      ++points;
      if (lowest < 0.0) {
        ++outside;
        EXPECT_EQ(proj.size(), 0u) << "E'Q misses the triangle";
        continue;
      }
      ++inside;
      ASSERT_EQ(proj.size(), 1u) << "E'Q crosses the triangle";
      const dvec3 base = fanPoint(fan, proj[0].w, 0.0);
      const double scale = 1.0 + glm::length(q);
      const double error = glm::length(base - hit) / scale;
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-4) << "size " << size;
      EXPECT_LE(distanceToLine(base, mirrored, q) / scale, 1e-4) << "P on E'Q";
    }
  }
  std::printf(
      "planar mirror: %d points (%d through the triangle, %d beside it), worst reflection "
      "point error %.2e\n",
      points, inside, outside, worst);
}

TEST(C3rcReflector, SphereFollowsTheLawOfReflectionAsTrianglesShrink) {
  // A small triangle of a tessellated sphere (normals radial), convex (eye outside) and concave
  // (eye inside): the reflector point P that sees Q must reflect the eye ray into Q with the
  // interpolated normal. The C3RC interpolates rays linearly, so the angle error falls as the
  // square of the triangle's size: checked at 0.1, 0.03 and 0.01.
  double worst_at[3] = {};
  const float sizes[3] = {0.1f, 0.03f, 0.01f};
  int points = 0;
  for (int s = 0; s < 3; ++s) {
    Rng rng(99);
    const float size = sizes[s];
    for (int trial = 0; trial < 100; ++trial) {
      const bool concave = trial % 2 == 1;
      const vec3 toward_eye = randomUnit(rng);
      const vec3 eye = toward_eye * (concave ? 0.5f : 3.0f);
      const vec3 axis = concave ? -randomInCone(rng, toward_eye, radians(50.0f))
                                : randomInCone(rng, toward_eye, radians(60.0f));
      const vec3 tx = tangentOf(axis), ty = glm::cross(axis, tx);
      vec3 v[3], n[3];
      const float a0 = uniformIn(rng, 0.0f, 2.0f * kPi);
      for (int k = 0; k < 3; ++k) {
        float a = a0 + 2.0f * kPi * float(k) / 3.0f + uniformIn(rng, -0.3f, 0.3f);
        v[k] = glm::normalize(axis + size * (std::cos(a) * tx + std::sin(a) * ty));
        n[k] = concave ? -v[k] : v[k];
      }
      const C3rcData c = reflectorC3rc(eye, v, n, 5.0f);
      const Fan fan = fanOf(c);
      const dvec3 e(eye);
      auto normalAt = [&](const std::array<double, 3>& w) {
        return glm::normalize(w[0] * dvec3(n[0]) + w[1] * dvec3(n[1]) + w[2] * dvec3(n[2]));
      };
      for (int i = 0; i < 20; ++i) {
        const vec3 w = randomBarycentrics(rng, 0.05f);
        const std::array<double, 3> wd = {double(w.x), double(w.y), double(w.z)};
        const dvec3 p = fanPoint(fan, wd, 0.0);
        const dvec3 ray = glm::reflect(glm::normalize(p - e), normalAt(wd));
        // Concave: short of the point where the rays converge (0.75 or more from the mirror
        // here), where T(λ) collapses and the projection is ill-conditioned.
        const float far = concave ? uniformIn(rng, 0.05f, 0.5f) : uniformIn(rng, 0.5f, 3.0f);
        const dvec3 q = dvec3(vec3(p + ray * double(far)));
        const auto proj = analyticProjections(c, vec3(q));
        ++points;
        ASSERT_FALSE(proj.empty()) << "size " << size;
        double best = kInfinity;  // a concave C3RC may see Q more than once: the best one
        for (const Projection& pr : proj) {
          const dvec3 base = fanPoint(fan, pr.w, 0.0);
          const dvec3 r = glm::reflect(glm::normalize(base - e), normalAt(pr.w));
          best = std::min(best, std::acos(std::min(1.0, glm::dot(r, glm::normalize(q - base)))));
        }
        worst_at[s] = std::max(worst_at[s], best);
      }
    }
  }
  std::printf(
      "sphere: %d points, worst angle error %.2e / %.2e / %.2e rad at sizes 0.1 / 0.03 / "
      "0.01\n",
      points, worst_at[0], worst_at[1], worst_at[2]);
  for (int s = 0; s < 3; ++s)
    EXPECT_LE(worst_at[s], 3.0 * double(sizes[s]) * double(sizes[s])) << "size " << sizes[s];
  EXPECT_LE(worst_at[2], 3e-4);
}

// ---------------------------------------------------------------------------------------------
// Transforms.

TEST(C3rcTransform, ProjectionIsInvariantUnderAffineMaps) {
  Rng rng(4242);
  int compared = 0, skipped = 0;
  double worst = 0.0;
  for (int trial = 0; trial < 120; ++trial) {
    const Family family = Family(trial % kFamilies);
    const Triangle t = randomTriangle(rng);
    const Rays rays = familyRays(family, t, rng);
    const C3rcData c = cameraOf(t, rays.d);
    const Fan fan = fanOf(c);
    const quat rotation = glm::angleAxis(uniformIn(rng, 0.0f, 2.0f * kPi), randomUnit(rng));
    const vec3 shift(uniformIn(rng, -3.0f, 3.0f), uniformIn(rng, -3.0f, 3.0f),
                     uniformIn(rng, -3.0f, 3.0f));
    mat4 m = glm::translate(mat4(1.0f), shift) * glm::mat4_cast(rotation);
    if (trial % 2 == 1)  // non-uniform scale, then another rotation
      m = m * glm::scale(mat4(1.0f), vec3(0.5f, 2.0f, 1.3f)) *
          glm::mat4_cast(glm::angleAxis(uniformIn(rng, 0.0f, 2.0f * kPi), randomUnit(rng)));
    const C3rcData moved = transformC3rc(c, m);
    const Fan moved_fan = fanOf(moved);
    EXPECT_EQ(moved.info.w, c.info.w) << "λ is unchanged";
    for (int i = 0; i < 10; ++i) {
      const vec3 w = randomBarycentrics(rng, 0.05f);
      const vec3 q(fanPoint(fan, {double(w.x), double(w.y), double(w.z)},
                            double(uniformIn(rng, 0.0f, rays.depth))));
      const auto a = analyticProjections(c, q);
      const auto b = analyticProjections(moved, transformPoint(m, q));
      bool ambiguous = false;
      for (const auto* list : {&a, &b})
        for (const Projection& p : *list)
          ambiguous = ambiguous || p.lowest() < kBoundary ||
                      conditioning(fan, p) < kConditioningMin ||
                      sweptSize(fan, p.lambda) < kCollapseMin * fan.size;
      if (ambiguous) {
        ++skipped;
        continue;
      }
      ++compared;
      ASSERT_EQ(a.size(), b.size()) << kFamilyNames[family];
      for (size_t k = 0; k < a.size(); ++k) {
        // Both float: each misses q by its residual, which moves it by about |J⁻¹| r (as in
        // the sweep).
        const double ra = glm::length(fanPoint(fan, a[k].w, a[k].lambda) - dvec3(q));
        const double rb =
            glm::length(fanPoint(moved_fan, b[k].w, b[k].lambda) - dvec3(transformPoint(m, q)));
        const double spread = frobenius(glm::inverse(fanJacobian(fan, a[k])));
        const double spread_moved = frobenius(glm::inverse(fanJacobian(moved_fan, b[k])));
        const double e = projectionDistance(b[k], a[k]);
        worst = std::max(worst, e);
        EXPECT_LE(e, kMatchTolerance + 2.0 * (spread * ra + spread_moved * rb))
            << kFamilyNames[family] << (trial % 2 ? " scaled" : " rigid");
      }
    }
  }
  std::printf("transforms: %d points compared, %d skipped as ambiguous, worst difference %.2e\n",
              compared, skipped, worst);
  EXPECT_LT(skipped, compared / 10);
}

// ---------------------------------------------------------------------------------------------
// Degenerate input.

// Whatever the input: at most three projections, each finite, in the simplex (to eps) and at
// 0 ≤ λ ≤ λmax. Returns the count.
int checkedProjections(const C3rcData& c, const vec3& q, std::vector<Projection>* out = nullptr) {
  vec4 p[3];
  const int n = shading::c3rc_project(c, q, kEps, false, p[0], p[1], p[2]);
  EXPECT_GE(n, 0);
  EXPECT_LE(n, 3);
  for (int i = 0; i < std::min(n, 3); ++i) {
    EXPECT_TRUE(std::isfinite(p[i].x) && std::isfinite(p[i].y) && std::isfinite(p[i].z) &&
                std::isfinite(p[i].w))
        << "projection " << i << " of " << n;
    EXPECT_GE(std::min({p[i].x, p[i].y, p[i].z}), -kEps);
    EXPECT_GE(p[i].w, 0.0f);
    if (std::isfinite(c.info.w)) {
      EXPECT_LE(p[i].w, c.info.w);
    }
    if (out) out->push_back({{double(p[i].x), double(p[i].y), double(p[i].z)}, double(p[i].w)});
  }
  return n;
}

TEST(C3rcRobustness, DegenerateInputGivesNoNaNs) {
  Rng rng(555);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto randomPoint = [&] {
    return vec3(uniformIn(rng, -2.0f, 2.0f), uniformIn(rng, -2.0f, 2.0f),
                uniformIn(rng, -2.0f, 2.0f));
  };
  int found = 0, calls = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const Triangle t = randomTriangle(rng);
    const Rays rays = familyRays(Family(trial % kFamilies), t, rng);
    const auto& d = rays.d;
    const vec3 mid = 0.5f * (t.v[0] + t.v[1]);
    std::vector<C3rcData> cameras = {
        makeC3rc(t.v[0], t.v[0], t.v[0], d[0], d[1], d[2], kLambdaMax),  // a point: a pinhole
        makeC3rc(t.v[0], t.v[1], mid, d[0], d[1], d[2], kLambdaMax),     // collinear vertices
        makeC3rc(t.v[0], t.v[0], t.v[0], d[0], d[0], d[0], kLambdaMax),  // a single ray
        makeC3rc(t.v[0], t.v[1], t.v[2], d[0], d[0], d[1], kLambdaMax),  // two equal rays
        makeC3rc(t.v[0], t.v[1], t.v[2], vec3(0.0f), vec3(0.0f), vec3(0.0f), kLambdaMax),
        makeC3rc(vec3(nan, 0.0f, 0.0f), t.v[1], t.v[2], d[0], d[1], d[2], kLambdaMax),
        makeC3rc(t.v[0], t.v[1], t.v[2], d[0], vec3(0.0f, nan, 0.0f), d[2], kLambdaMax),
        makeC3rc(t.v[0], t.v[1], t.v[2], d[0], d[1], vec3(kInfinity, 0.0f, 0.0f), kLambdaMax),
        makeC3rc(t.v[0], t.v[1], t.v[2], d[0], d[1], d[2], nan),
    };
    const vec3 normals[3] = {t.normal(), t.normal(), t.normal()};
    const vec3 degenerate[3] = {t.v[0], t.v[0], t.v[0]};
    const vec3 with_nan[3] = {t.v[0], vec3(nan), t.v[2]};
    const vec3 zero_normals[3] = {vec3(0.0f), vec3(0.0f), vec3(0.0f)};
    cameras.push_back(reflectorC3rc(vec3(0.0f, 0.0f, 5.0f), degenerate, normals, 10.0f));
    cameras.push_back(reflectorC3rc(vec3(0.0f, 0.0f, 5.0f), with_nan, normals, 10.0f));
    cameras.push_back(reflectorC3rc(t.v[0], t.v.data(), normals, 10.0f));  // the eye on a vertex
    cameras.push_back(reflectorC3rc(vec3(0.0f, 0.0f, 5.0f), t.v.data(), zero_normals, 10.0f));
    cameras.push_back(reflectorC3rc(vec3(nan), t.v.data(), normals, 10.0f));
    for (const C3rcData& c : cameras) {
      for (int i = 0; i < 20; ++i) found += checkedProjections(c, randomPoint()) > 0;
      for (const vec3& q : t.v) checkedProjections(c, q);
      checkedProjections(c, vec3(nan));
      checkedProjections(c, vec3(kInfinity));
      calls += 23;
    }
  }
  std::printf("degenerate cameras: %d projections checked, %d points seen\n", calls, found);
}

TEST(C3rcRobustness, ParallelRaysAreAnOrthographicCamera) {
  // d0 = d1 = d2: the normal n(λ) is constant, the cubic linear; Q projects once, along the
  // common ray onto the base triangle.
  Rng rng(808);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Triangle t = randomTriangle(rng);
    const vec3 ray = randomInCone(rng, t.normal(), radians(60.0f));
    const C3rcData c = makeC3rc(t.v[0], t.v[1], t.v[2], ray, ray, ray, kLambdaMax);
    EXPECT_FALSE(int(c.info.z) & MIRAGE_C3RC_MULTIPLE);
    const Fan fan = fanOf(c);
    const dvec3 nn = glm::cross(fan.v[1] - fan.v[0], fan.v[2] - fan.v[0]);
    for (int i = 0; i < 20; ++i) {
      // Over the triangle grown by 30 % about its centroid, from λ = −1 to 3.
      const vec3 w = (randomBarycentrics(rng, 0.0f) - vec3(1.0f / 3.0f)) * 1.3f + vec3(1.0f / 3.0f);
      const dvec3 q = dvec3(vec3(fanPoint(fan, {double(w.x), double(w.y), double(w.z)}, 0.0) +
                                 fan.d[0] * double(uniformIn(rng, -1.0f, 3.0f))));
      const double lambda = glm::dot(nn, q - fan.v[0]) / glm::dot(nn, fan.d[0]);
      const dvec3 base = q - lambda * fan.d[0];
      const double area = glm::dot(nn, nn);
      const Projection exact{{glm::dot(glm::cross(fan.v[1] - base, fan.v[2] - base), nn) / area,
                              glm::dot(glm::cross(fan.v[2] - base, fan.v[0] - base), nn) / area,
                              glm::dot(glm::cross(fan.v[0] - base, fan.v[1] - base), nn) / area},
                             lambda};
      std::vector<Projection> proj;
      const int n = checkedProjections(c, vec3(q), &proj);
      if (std::abs(exact.lowest()) < kBoundary) continue;
      if (exact.lowest() < 0.0) {
        ++outside;
        EXPECT_EQ(n, 0);
        continue;
      }
      ++inside;
      ASSERT_EQ(n, 1);
      EXPECT_LE(projectionDistance(proj[0], exact), 1e-5 / std::min(1.0, fan.size));
    }
  }
  std::printf("orthographic: %d points projected, %d outside\n", inside, outside);
  EXPECT_GT(inside, 800);
}

TEST(C3rcRobustness, PointsOnTheBaseTriangle) {
  // λ = 0: Q on the reflector itself. Rounding may put the root a hair below 0 (then it is
  // missed), but a projection that is found is the point itself.
  Rng rng(909);
  int points = 0, found = 0;
  for (int trial = 0; trial < 90; ++trial) {
    const Triangle t = randomTriangle(rng);
    const Rays rays = familyRays(Family(trial % kFamilies), t, rng);
    const C3rcData c = cameraOf(t, rays.d);
    const Fan fan = fanOf(c);
    for (int i = 0; i < 20; ++i) {
      const vec3 w = randomBarycentrics(rng, 0.02f);
      const std::array<double, 3> wd = {double(w.x), double(w.y), double(w.z)};
      const vec3 q(fanPoint(fan, wd, 0.0));
      std::vector<Projection> proj;
      checkedProjections(c, q, &proj);
      ++points;
      for (const Projection& p : proj) {
        if (p.lambda > 1e-3) continue;  // another sheet of a folded C3RC
        ++found;
        EXPECT_LE(projectionDistance(p, {wd, 0.0}), 1e-4);
      }
    }
  }
  std::printf("base triangle: %d of %d points found at λ ≈ 0\n", found, points);
  RecordProperty("base_points_found", found);
}

// ---------------------------------------------------------------------------------------------
// The cubic.

struct Cubic {
  vec4 p;                     // c0 + c1 x + c2 x² + c3 x³, as the shared code stores it
  std::vector<double> roots;  // its distinct real roots
};

// a (x − r1)(x − r2)(x − r3) with the roots multiples of 1/8 in [0, 10] and a a power of two:
// every coefficient is exact in float, so the float cubic has exactly these roots.
Cubic exactCubic(Rng& rng, bool double_root) {
  std::uniform_int_distribution<int> eighths(0, 80), exponent(-27, 6);
  for (;;) {
    const double r1 = eighths(rng) / 8.0, r3 = eighths(rng) / 8.0;
    const double r2 = double_root ? r1 : eighths(rng) / 8.0;
    if (std::abs(r1 - r3) < 0.5 ||
        (!double_root && (std::abs(r1 - r2) < 0.5 || std::abs(r2 - r3) < 0.5)))
      continue;  // well separated: a near-double root is the double-root case
    const double a = std::ldexp(rng() % 2 ? 1.0 : -1.0, exponent(rng));
    Cubic c;
    c.p = vec4(float(-a * r1 * r2 * r3), float(a * (r1 * r2 + r1 * r3 + r2 * r3)),
               float(-a * (r1 + r2 + r3)), float(a));
    c.roots = {r1, r3};
    if (!double_root) c.roots.push_back(r2);
    return c;
  }
}

// Checks c3rc_cubic_roots on `cubic` in [0, lambda_max]: every root in range found within 1e-4
// (relative beyond 1), nothing else. Returns false where a root was missed.
bool checkRoots(const Cubic& cubic, float lambda_max, const char* what) {
  vec3 found(0.0f);
  const int n = shading::c3rc_cubic_roots(cubic.p, lambda_max, found);
  EXPECT_GE(n, 0);
  EXPECT_LE(n, 3);
  const double tolerance = 1e-4;
  std::vector<double> got;
  for (int i = 0; i < std::min(n, 3); ++i) got.push_back(double(found[i]));
  for (size_t i = 1; i < got.size(); ++i) EXPECT_GE(got[i], got[i - 1]) << what << ": ascending";
  for (double g : got) {
    bool near = false;
    for (double r : cubic.roots) near = near || std::abs(g - r) <= tolerance * std::max(1.0, r);
    EXPECT_TRUE(near) << what << ": " << g << " is no root of (" << cubic.p.x << ", " << cubic.p.y
                      << ", " << cubic.p.z << ", " << cubic.p.w << ")";
  }
  bool all = true;
  for (double r : cubic.roots) {
    if (r < 0.0 || r > double(lambda_max)) continue;
    bool hit = false;
    for (double g : got) hit = hit || std::abs(g - r) <= tolerance * std::max(1.0, r);
    all = all && hit;
  }
  return all;
}

TEST(C3rcCubic, RootsOfKnownCubics) {
  Rng rng(31337);
  const float lambda_max = 9.9f;  // some roots (up to 10) lie beyond it
  int missed_simple = 0, missed_double = 0, cases = 0;
  for (int i = 0; i < 2000; ++i) {
    const Cubic simple = exactCubic(rng, false);
    missed_simple += !checkRoots(simple, lambda_max, "simple roots");
    const Cubic twice = exactCubic(rng, true);
    missed_double += !checkRoots(twice, lambda_max, "a double root");
    cases += 2;
  }
  // A double root whose coefficients round in float (any real r): the float cubic then has two
  // roots within ~sqrt(1e-7) relative of r, or none; either way it touches zero at a critical
  // point within float precision of r, and that must be reported.
  int missed_rounded_double = 0;
  {
    std::uniform_real_distribution<double> where(0.0, 10.0), lead(-3.0, 3.0);
    for (int i = 0; i < 2000; ++i) {
      const double r = where(rng), r3 = where(rng),
                   a = std::pow(10.0, lead(rng)) * (i % 2 ? 1 : -1);
      // (Not at the ends of the range: the touching point may then fall just outside it.)
      if (std::abs(r - r3) < 0.5 || r < 0.05 || std::abs(r - double(lambda_max)) < 0.05) continue;
      Cubic twice;
      twice.p = vec4(float(-a * r * r * r3), float(a * (r * r + 2.0 * r * r3)),
                     float(-a * (2.0 * r + r3)), float(a));
      twice.roots = {r, r3};
      missed_rounded_double += !checkRoots(twice, lambda_max, "a rounded double root");
      ++cases;
    }
  }
  // Nearly quadratic and nearly linear: (x − r1)(x − r2)(εx − 1) and (x − r1)(εx − 1)(ε'x − 1),
  // ε ~ 1e-8: the other roots are ~1e8, far beyond λmax; the leading coefficient ~1e-8 and
  // ~1e-16. Then exactly quadratic and linear (c3 = 0, c2 = 0).
  int missed_degenerate = 0;
  std::uniform_real_distribution<double> root(0.0, 10.0), tiny(0.5e-8, 2e-8), gain(0.1, 10.0);
  for (int i = 0; i < 500; ++i) {
    const double r1 = root(rng), r2 = root(rng), e1 = tiny(rng), e2 = tiny(rng), g = gain(rng);
    if (std::abs(r1 - r2) < 0.5) continue;
    Cubic quadratic;  // g (x − r1)(x − r2)(1 − εx): roots r1, r2, 1/ε
    quadratic.p = vec4(float(g * r1 * r2), float(-g * (r1 + r2 + e1 * r1 * r2)),
                       float(g * (1.0 + e1 * (r1 + r2))), float(-g * e1));
    quadratic.roots = {r1, r2};
    Cubic linear;  // g (x − r1)(1 − ε x)(1 − ε' x): roots r1, 1/ε, 1/ε'
    linear.p = vec4(float(-g * r1), float(g * (1.0 + r1 * (e1 + e2))),
                    float(-g * (e1 + e2 + r1 * e1 * e2)), float(g * e1 * e2));
    linear.roots = {r1};
    Cubic exact_quadratic = quadratic, exact_linear = linear;
    exact_quadratic.p.w = 0.0f;
    exact_linear.p.z = exact_linear.p.w = 0.0f;
    missed_degenerate += !checkRoots(quadratic, lambda_max, "nearly quadratic");
    missed_degenerate += !checkRoots(linear, lambda_max, "nearly linear");
    exact_quadratic.roots = {r1, r2};
    missed_degenerate += !checkRoots(exact_quadratic, lambda_max, "quadratic");
    missed_degenerate += !checkRoots(exact_linear, lambda_max, "linear");
    cases += 4;
  }
  std::printf(
      "cubic roots: %d cubics, missed: %d with simple roots, %d with a double root (%d "
      "rounded), %d nearly quadratic or linear\n",
      cases, missed_simple, missed_double, missed_rounded_double, missed_degenerate);
  EXPECT_EQ(missed_simple, 0);
  EXPECT_EQ(missed_degenerate, 0);
  EXPECT_EQ(missed_double, 0) << "a double root (Q on a caustic)";
  EXPECT_EQ(missed_rounded_double, 0) << "a double root must not be lost to rounding";
}

}  // namespace
}  // namespace mirage
