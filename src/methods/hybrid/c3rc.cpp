#include "methods/hybrid/c3rc.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shading/shading.h"

namespace mirage {

namespace {

// T(λ) has collapsed to a segment or a point while all three rays lie in its plane, or has not
// collapsed and they do (coplanar rays parallel to it): the second case makes every w critical.
bool raysInAnOpenPlane(const C3rcData& c, float lambda) {
  const vec3 n = shading::c3rc_normal(c, lambda);
  const float size = glm::length(vec3(c.n0)) +
                     lambda * (glm::length(vec3(c.n1)) + lambda * glm::length(vec3(c.n2)));
  if (!(glm::length(n) > 1e-6f * size)) return false;  // collapsed: T(λ) is its own edges
  for (const vec4& d : {c.d0, c.d1, c.d2})
    if (std::abs(glm::dot(vec3(d), n)) > 1e-6f * glm::length(n) * glm::length(vec3(d)))
      return false;
  return true;
}

// Fills info.xy, folds and the MIRAGE_C3RC_MULTIPLE flag. The sidedness quadratics' roots split
// [0, λmax] into pieces on which each ray keeps its side of T(λ); the pieces where the sides are
// mixed, merged where they touch (and a root where every ray lies in an uncollapsed T(λ), as a
// point), are where T(λ) may fold. info.xy is their hull; folds holds them as two intervals,
// the closest neighbours merged while there are more (the ranges only grow: still conservative).
void findFolds(C3rcData& c) {
  std::array<float, 8> breaks{};
  int n = 0;
  breaks[size_t(n++)] = 0.0f;
  for (const vec4& d : {c.d0, c.d1, c.d2}) {
    float r0 = 0.0f, r1 = 0.0f;
    int k = shading::c3rc_side_crossings(c, vec3(d), r0, r1);
    if (k >= 1 && r0 < c.info.w) breaks[size_t(n++)] = r0;
    if (k >= 2 && r1 < c.info.w) breaks[size_t(n++)] = r1;
  }
  breaks[size_t(n++)] = c.info.w;
  for (int i = 1; i < n; ++i)  // insertion sort of at most 8 values
    for (int j = i; j > 0 && breaks[size_t(j - 1)] > breaks[size_t(j)]; --j)
      std::swap(breaks[size_t(j - 1)], breaks[size_t(j)]);
  std::array<vec2, 16> runs{};
  int count = 0;
  auto add = [&](float a, float b) {
    if (count > 0 && runs[size_t(count - 1)].y >= a)
      runs[size_t(count - 1)].y = std::max(runs[size_t(count - 1)].y, b);
    else
      runs[size_t(count++)] = vec2(a, b);
  };
  for (int i = 0; i + 1 < n; ++i) {
    const float a = breaks[size_t(i)], b = breaks[size_t(i + 1)];
    if (i > 0 && raysInAnOpenPlane(c, a)) add(a, a);
    if (b > a && !shading::c3rc_sides_agree(c, 0.5f * (a + b))) add(a, b);
  }
  while (count > 2) {  // merge the two neighbours with the smallest gap
    int closest = 0;
    for (int i = 1; i + 1 < count; ++i)
      if (runs[size_t(i + 1)].x - runs[size_t(i)].y <
          runs[size_t(closest + 1)].x - runs[size_t(closest)].y)
        closest = i;
    runs[size_t(closest)].y = runs[size_t(closest + 1)].y;
    for (int i = closest + 1; i + 1 < count; ++i) runs[size_t(i)] = runs[size_t(i + 1)];
    --count;
  }
  const vec2 empty(1.0f, 0.0f);
  const vec2 first = count >= 1 ? runs[0] : empty, second = count >= 2 ? runs[1] : empty;
  c.folds = vec4(first, second);
  c.info.x = count >= 1 ? first.x : 1.0f;
  c.info.y = count >= 1 ? runs[size_t(count - 1)].y : 0.0f;
  c.info.z = count >= 1 ? float(MIRAGE_C3RC_MULTIPLE) : 0.0f;
}

// Fills the hull: planes through a base edge along a ray, the base plane, planes through a vertex
// along two rays — each valid when no ray leads out of it (a·d_k ≤ 0, exactly), so that the base
// swept along the cone of the rays, which holds the view volume, lies behind it.
void findHull(C3rcData& c) {
  const vec3 v[3] = {vec3(c.v0), vec3(c.v1), vec3(c.v2)};
  const vec3 d[3] = {vec3(c.d0), vec3(c.d1), vec3(c.d2)};
  std::array<vec3, 13> candidates{};
  size_t n = 0;
  for (int e = 0; e < 3; ++e)
    for (int k = 0; k < 3; ++k) candidates[n++] = glm::cross(v[(e + 1) % 3] - v[e], d[k]);
  candidates[n++] = glm::cross(v[1] - v[0], v[2] - v[0]);
  for (int k = 0; k < 3; ++k) candidates[n++] = glm::cross(d[k], d[(k + 1) % 3]);
  c.counts = ivec4(0);
  for (const vec3& candidate : candidates) {
    const float len = glm::length(candidate);
    if (!(len > 0.0f) || !std::isfinite(len)) continue;
    for (float sign : {1.0f, -1.0f}) {
      const vec3 a = sign * candidate / len;
      if (glm::dot(a, d[0]) > 0.0f || glm::dot(a, d[1]) > 0.0f || glm::dot(a, d[2]) > 0.0f)
        continue;
      if (c.counts.x == MIRAGE_C3RC_HULL) return;
      const float h = std::max({glm::dot(a, v[0]), glm::dot(a, v[1]), glm::dot(a, v[2])});
      c.hull[c.counts.x++] = vec4(a, h);
    }
  }
}

}  // namespace

C3rcData makeC3rc(const vec3& v0, const vec3& v1, const vec3& v2, const vec3& d0, const vec3& d1,
                  const vec3& d2, float lambda_max) {
  C3rcData c{};
  c.v0 = vec4(v0, 1.0f);
  c.v1 = vec4(v1, 1.0f);
  c.v2 = vec4(v2, 1.0f);
  c.d0 = vec4(d0, 0.0f);
  c.d1 = vec4(d1, 0.0f);
  c.d2 = vec4(d2, 0.0f);
  vec3 n0, n1, n2;
  shading::c3rc_normal_coefficients(v0, v1, v2, d0, d1, d2, n0, n1, n2);
  c.n0 = vec4(n0, 0.0f);
  c.n1 = vec4(n1, 0.0f);
  c.n2 = vec4(n2, 0.0f);
  c.info = vec4(1.0f, 0.0f, 0.0f, lambda_max);
  findFolds(c);
  findHull(c);
  return c;
}

C3rcData reflectorC3rc(const vec3& eye, const vec3 v[3], const vec3 n[3], float reach,
                       bool eye_scaled) {
  vec3 geometric = glm::cross(v[1] - v[0], v[2] - v[0]);
  vec3 d[3];
  for (int k = 0; k < 3; ++k) {
    vec3 to_eye = glm::normalize(eye - v[k]);
    vec3 normal = shading::facing_normal(n[k], geometric, to_eye);
    // Scaled by the vertex's distance to the eye, so that the rays leave the mirrored eye E' in
    // step: on a plane v_k + λ d_k = E' + (1 + λ)(v_k − E'), and the C3RC is exactly the
    // pinhole camera at E'. Unit rays bend a planar mirror's image (by 7 % of a unit triangle's
    // size seen from 1 to 3 units away).
    d[k] = glm::normalize(shading::reflect_direction(-to_eye, normal)) *
           (eye_scaled ? glm::length(eye - v[k]) : 1.0f);
  }
  float shortest = std::max(distanceToTriangle(d[0], d[1], d[2]), 1e-3f);
  return makeC3rc(v[0], v[1], v[2], d[0], d[1], d[2], reach / shortest);
}

C3rcData transformC3rc(const C3rcData& c, const mat4& m) {
  mat3 l(m);
  auto point = [&](const vec4& p) { return vec3(m * vec4(vec3(p), 1.0f)); };
  C3rcData out = makeC3rc(point(c.v0), point(c.v1), point(c.v2), l * vec3(c.d0), l * vec3(c.d1),
                          l * vec3(c.d2), c.info.w);
  return out;
}

float distanceToTriangle(const vec3& a, const vec3& b, const vec3& c) {
  // Ericson, Real-Time Collision Detection §5.1.5: the closest point of the triangle to p = 0.
  const vec3 p(0.0f);
  vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return glm::length(a);
  vec3 bp = p - b;
  float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return glm::length(b);
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::length(a + ab * (d1 / (d1 - d3)));
  vec3 cp = p - c;
  float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return glm::length(c);
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::length(a + ac * (d2 / (d2 - d6)));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return glm::length(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  float denom = 1.0f / (va + vb + vc);
  return glm::length(a + ab * (vb * denom) + ac * (vc * denom));
}

}  // namespace mirage
