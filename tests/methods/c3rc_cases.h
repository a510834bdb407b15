// Random C3RC cases and a brute-force search of a C3RC's ray fan, shared by the C3RC tests
// (c3rc_projection_test.cpp: projection, sidedness, shared edges; c3rc_camera_test.cpp: the
// reflected-ray camera, transforms, degenerate input, the cubic). Seeded: the same cases run
// every time.
#pragma once

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

namespace mirage::c3rc_cases {

using glm::dvec3;
using Rng = std::mt19937;

constexpr float kEps = 1e-5f;         // the barycentric slack c3rc_project is called with
constexpr float kShaderEps = 1e-4f;   // the slack of the splatting shader and the culling
constexpr float kLambdaMax = 100.0f;  // far beyond every test point (λ ≤ ~10 there)

inline float uniformIn(Rng& rng, float lo, float hi) {
  return std::uniform_real_distribution<float>(lo, hi)(rng);
}

inline vec3 randomUnit(Rng& rng) {
  std::normal_distribution<float> normal(0.0f, 1.0f);
  for (;;) {
    vec3 v(normal(rng), normal(rng), normal(rng));
    float l = glm::length(v);
    if (l > 1e-3f) return v / l;
  }
}

// A unit vector uniformly distributed over the cone of half-angle `angle` around the unit `axis`.
inline vec3 randomInCone(Rng& rng, const vec3& axis, float angle) {
  float cz = uniformIn(rng, std::cos(angle), 1.0f);
  float sz = std::sqrt(std::max(0.0f, 1.0f - cz * cz));
  float phi = uniformIn(rng, 0.0f, 2.0f * kPi);
  vec3 t = glm::normalize(
      glm::cross(axis, std::abs(axis.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
  vec3 b = glm::cross(axis, t);
  return glm::normalize(cz * axis + sz * (std::cos(phi) * t + std::sin(phi) * b));
}

// Barycentrics with every w_k ≥ lo, uniform over that sub-simplex (rejection from uniform).
inline vec3 randomBarycentrics(Rng& rng, float lo) {
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
inline Triangle randomTriangle(Rng& rng) {
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
inline const char* const kFamilyNames[kFamilies] = {"divergent", "convergent", "random"};

// Unit construction rays of one family for the triangle, and the depth (the largest λ) of the
// region worth probing: where the family's projections are interesting.
struct Rays {
  std::array<vec3, 3> d{};
  float depth = 3.0f;
};

inline Rays familyRays(Family family, const Triangle& t, Rng& rng) {
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

inline C3rcData cameraOf(const Triangle& t, const std::array<vec3, 3>& d) {
  return makeC3rc(t.v[0], t.v[1], t.v[2], d[0], d[1], d[2], kLambdaMax);
}

// A projection: barycentrics and λ, in double whichever side computed it.
struct Projection {
  std::array<double, 3> w{};
  double lambda = 0.0;
  double lowest() const { return std::min({w[0], w[1], w[2], lambda}); }
};

inline std::vector<Projection> analyticProjections(const C3rcData& c, const vec3& q,
                                                   float eps = kEps) {
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

inline Fan fanOf(const C3rcData& c) {
  Fan f;
  f.v = {dvec3(vec3(c.v0)), dvec3(vec3(c.v1)), dvec3(vec3(c.v2))};
  f.d = {dvec3(vec3(c.d0)), dvec3(vec3(c.d1)), dvec3(vec3(c.d2))};
  f.lambda_max = double(c.info.w);
  f.size = std::max(
      {glm::length(f.v[1] - f.v[0]), glm::length(f.v[2] - f.v[1]), glm::length(f.v[0] - f.v[2])});
  return f;
}

// The point of the fan's ray w at λ: v(w) + λ d(w).
inline dvec3 fanPoint(const Fan& f, const std::array<double, 3>& w, double lambda) {
  dvec3 p(0.0);
  for (size_t k = 0; k < 3; ++k) p += w[k] * (f.v[k] + lambda * f.d[k]);
  return p;
}

// The longest edge of the swept triangle T(λ).
inline double sweptSize(const Fan& f, double lambda) {
  dvec3 q[3];
  for (size_t k = 0; k < 3; ++k) q[k] = f.v[k] + lambda * f.d[k];
  return std::max({glm::length(q[1] - q[0]), glm::length(q[2] - q[1]), glm::length(q[0] - q[2])});
}

// The Jacobian of (w0, w1, λ) ↦ v(w) + λ d(w) (w2 = 1 − w0 − w1) at a projection: the edges
// p0 − p2, p1 − p2 of T(λ) (p_k = v_k + λ d_k) and the ray d(w).
inline glm::dmat3 fanJacobian(const Fan& f, const Projection& p) {
  dvec3 q[3];
  for (size_t k = 0; k < 3; ++k) q[k] = f.v[k] + p.lambda * f.d[k];
  dvec3 dw = p.w[0] * f.d[0] + p.w[1] * f.d[1] + p.w[2] * f.d[2];
  return glm::dmat3(q[0] - q[2], q[1] - q[2], dw);
}

inline double frobenius(const glm::dmat3& m) {
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
inline double conditioning(const Fan& f, const Projection& p) {
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
inline double newtonOnFan(const Fan& f, const dvec3& q, std::array<double, 3>& x) {
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
inline BruteForce bruteForce(const Fan& f, const dvec3& q) {
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
inline double projectionDistance(const Projection& a, const Projection& b) {
  double e = std::abs(a.lambda - b.lambda) / std::max(1.0, std::abs(b.lambda));
  for (size_t k = 0; k < 3; ++k) e = std::max(e, std::abs(a.w[k] - b.w[k]));
  return e;
}

// Tolerances of the comparisons with the brute force (see C3rcProject.MatchesBruteForce).
constexpr double kConditioningMin = 0.02;  // below: a near-double root or a collapsed T(λ)
constexpr double kMatchTolerance = 1e-5;   // see MatchesBruteForce
constexpr double kExactTolerance = 1e-4;   // |v(w) + λ d(w) − Q| per unit of scene size

constexpr double kCollapseMin = 0.05;  // T(λ) smaller than this times the base: a focus

}  // namespace mirage::c3rc_cases
