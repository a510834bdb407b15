// The reflected-ray C3RC of a planar mirror and of a sphere, projection under affine transforms,
// degenerate input, and the cubic root finder of c3rc_shared.h.
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
  // About 40 % of the 2,000 points fall inside; how many exactly depends on the compiler's
  // rounding of the random draws (795 with clang -O1, the sanitizer build).
  EXPECT_GT(inside, 700);
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
