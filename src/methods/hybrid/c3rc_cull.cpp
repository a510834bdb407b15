#include "methods/hybrid/c3rc_cull.h"

#include <algorithm>
#include <cmath>

namespace mirage {

namespace {

// The slack both culling stages give a box, so that rounding never culls a box that touches the
// view volume (the tests then only err on the side of keeping).
float boxMargin(const Bounds3& box) {
  return 1e-4f * glm::length(box.extent()) + 1e-6f;
}

Bounds3 grown(const Bounds3& box) {
  const float margin = boxMargin(box);
  return {box.lo - vec3(margin), box.hi + vec3(margin)};
}

}  // namespace

bool hullRejects(const C3rcData& c, const Bounds3& box) {
  const vec3 centre = box.center(), half = 0.5f * box.extent();
  const float margin = boxMargin(box);
  for (int i = 0; i < c.counts.x; ++i) {
    const vec4& p = c.hull[i];
    const vec3 a = vec3(p);
    const float lowest = glm::dot(a, centre) - glm::dot(glm::abs(a), half);
    if (lowest > p.w + margin) return true;
  }
  return false;
}

bool triangleMeetsBox(const vec3& a, const vec3& b, const vec3& c, const Bounds3& box) {
  // Separating axes (Akenine-Möller): the box's 3 normals, the triangle's normal, and the 9
  // cross products of the triangle's edges with the box's axes.
  const vec3 centre = box.center(), half = 0.5f * box.extent();
  const vec3 p[3] = {a - centre, b - centre, c - centre};
  const vec3 edge[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};
  auto separated = [&](const vec3& axis) {
    const float r = glm::dot(glm::abs(axis), half);
    const float p0 = glm::dot(axis, p[0]), p1 = glm::dot(axis, p[1]), p2 = glm::dot(axis, p[2]);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
  };
  for (int i = 0; i < 3; ++i) {
    vec3 axis(0.0f);
    axis[i] = 1.0f;
    if (separated(axis)) return false;
    for (const vec3& e : edge)
      if (separated(glm::cross(e, axis))) return false;
  }
  return !separated(glm::cross(edge[0], edge[1]));
}

bool rayMeetsBox(const vec3& origin, const vec3& dir, const Bounds3& box) {
  float t0 = 0.0f, t1 = kInfinity;
  for (int i = 0; i < 3; ++i) {
    if (dir[i] == 0.0f) {
      if (origin[i] < box.lo[i] || origin[i] > box.hi[i]) return false;
      continue;
    }
    float a = (box.lo[i] - origin[i]) / dir[i], b = (box.hi[i] - origin[i]) / dir[i];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
    if (t0 > t1) return false;
  }
  return true;
}

bool segmentCrossesWall(const vec3& p, const vec3& q, const vec3& vi, const vec3& vj,
                        const vec3& di, const vec3& dj) {
  // Solve A + αE + λ(D + αF) = tU with A = vi − p, U = q − p: the components perpendicular to
  // U give two bilinear equations in (α, λ); eliminating λ leaves a quadratic in α.
  const vec3 U = q - p;
  const float uu = glm::dot(U, U);
  if (!(uu > 0.0f)) return false;  // a zero-length edge: the other edges of the box cover it
  const vec3 A = vi - p, E = vj - vi, D = di, F = dj - di;
  const vec3 helper = std::abs(U.x) < std::abs(U.y) && std::abs(U.x) < std::abs(U.z)
                          ? vec3(1, 0, 0)
                          : (std::abs(U.y) < std::abs(U.z) ? vec3(0, 1, 0) : vec3(0, 0, 1));
  const vec3 m1 = glm::normalize(glm::cross(U, helper));
  const vec3 m2 = glm::normalize(glm::cross(U, m1));
  const float a1 = glm::dot(m1, A), b1 = glm::dot(m1, E), c1 = glm::dot(m1, D),
              e1 = glm::dot(m1, F);
  const float a2 = glm::dot(m2, A), b2 = glm::dot(m2, E), c2 = glm::dot(m2, D),
              e2 = glm::dot(m2, F);
  const float qa = b1 * e2 - b2 * e1;
  const float qb = a1 * e2 + b1 * c2 - a2 * e1 - b2 * c1;
  const float qc = a1 * c2 - a2 * c1;
  const float scale = (std::abs(a1) + std::abs(b1) + std::abs(a2) + std::abs(b2)) *
                          (std::abs(c1) + std::abs(e1) + std::abs(c2) + std::abs(e2)) +
                      1e-30f;
  if (std::abs(qa) + std::abs(qb) + std::abs(qc) <= 1e-6f * scale) {
    const float ray_scale = std::abs(c1) + std::abs(e1) + std::abs(c2) + std::abs(e2);
    const float base_scale = std::abs(a1) + std::abs(b1) + std::abs(a2) + std::abs(b2) + 1e-30f;
    if (ray_scale > 1e-6f * (glm::length(D) + glm::length(F)))
      return true;  // the two equations agree along a curve: keep the box (conservative)
    // The wall's rays are parallel to the edge: only the ray at the α where the wall's base edge
    // meets the edge's line can touch it; then compare the two along that line.
    const bool first = std::abs(b1) >= std::abs(b2);
    const float b = first ? b1 : b2;
    if (std::abs(b) <= 1e-12f * base_scale)
      return std::abs(a1) + std::abs(a2) <= 1e-6f * base_scale;
    const float alpha = -(first ? a1 : a2) / b;
    if (alpha < -1e-4f || alpha > 1.0f + 1e-4f) return false;
    if (std::abs(first ? a2 + b2 * alpha : a1 + b1 * alpha) > 1e-5f * base_scale) return false;
    const float start = glm::dot(A + alpha * E, U) / uu;  // the ray's origin along the edge
    const float along = glm::dot(D + alpha * F, U);       // its direction along the edge
    return along >= 0.0f ? start <= 1.0f + 1e-4f : start >= -1e-4f;
  }
  float roots[2];
  int n = shading::c3rc_quadratic_roots(qa, qb, qc, roots[0], roots[1]);
  constexpr float kEps = 1e-4f;
  for (int i = 0; i < n; ++i) {
    const float alpha = roots[i];
    if (alpha < -kEps || alpha > 1.0f + kEps) continue;
    const float den1 = c1 + e1 * alpha, den2 = c2 + e2 * alpha;
    const bool first = std::abs(den1) >= std::abs(den2);
    const float den = first ? den1 : den2;
    if (std::abs(den) <= 1e-12f) return true;  // the ray at α is parallel: keep
    const float lambda = -(first ? a1 + b1 * alpha : a2 + b2 * alpha) / den;
    if (lambda < -kEps) continue;
    const vec3 x = A + alpha * E + lambda * (D + alpha * F);
    const float t = glm::dot(x, U) / uu;
    if (t >= -kEps && t <= 1.0f + kEps) return true;
  }
  return false;
}

bool boxMeetsViewVolume(const C3rcData& c, const Bounds3& original) {
  const Bounds3 box = grown(original);
  const vec3 v[3] = {vec3(c.v0), vec3(c.v1), vec3(c.v2)};
  const vec3 d[3] = {vec3(c.d0), vec3(c.d1), vec3(c.d2)};
  // Inside: one corner projects (every corner does when the box is inside).
  vec4 p0, p1, p2;
  if (shading::c3rc_project(c, box.lo, 1e-4f, true, p0, p1, p2) > 0) return true;
  if (triangleMeetsBox(v[0], v[1], v[2], box)) return true;
  for (int k = 0; k < 3; ++k)
    if (rayMeetsBox(v[k], d[k], box)) return true;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      vec3 from = box.lo;
      from[u] = (corner & 1) ? box.hi[u] : box.lo[u];
      from[w] = (corner & 2) ? box.hi[w] : box.lo[w];
      vec3 to = from;
      to[axis] = box.hi[axis];
      for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        if (segmentCrossesWall(from, to, v[k], v[j], d[k], d[j])) return true;
      }
    }
  }
  return false;
}

void cullLeaves(const KdTree& tree, const C3rcData& c, Culling culling,
                std::vector<uint32_t>& leaves, CullCounters& counters) {
  if (tree.empty()) return;
  const std::vector<KdNode>& nodes = tree.nodes();
  uint32_t stack[64 * 8];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const KdNode& node = nodes[index];
    if (culling != Culling::kNone) {
      ++counters.nodes_tested;
      if (hullRejects(c, node.bounds)) {
        ++counters.hull_rejects;
        continue;
      }
      if (culling == Culling::kExact && !boxMeetsViewVolume(c, node.bounds)) {
        ++counters.exact_rejects;
        continue;
      }
    }
    if (node.leaf()) {
      leaves.push_back(index);
      ++counters.leaves_kept;
      continue;
    }
    for (uint32_t k = 0; k < node.child_count; ++k) stack[top++] = node.first_child + k;
  }
}

}  // namespace mirage
