// The box tests of the view-volume culling (c3rc_cull.h explains and proves them), shared by the
// CPU culling (c3rc_cull.cpp) and the GPU one (hybrid_cull.comp), so that both paths run the same
// code on the same C3RC. Boxes are passed as (lo, hi); no arrays (the two languages spell them
// differently), so the three vertices, rays and walls are unrolled.
#ifndef MIRAGE_METHODS_HYBRID_C3RC_CULL_SHARED_H
#define MIRAGE_METHODS_HYBRID_C3RC_CULL_SHARED_H

#include "methods/hybrid/c3rc_shared.h"
#include "shading/glsl_compat.h"

// How a box stands to a C3RC's view volume (c3rc_cull.h proves the cases complete): disjoint
// (culled); met (a corner projects, or the base, the far cap, a construction ray or a side wall
// meets it); or none of those but it may meet a fold surface (kept).
#define MIRAGE_C3RC_BOX_OUT 0
#define MIRAGE_C3RC_BOX_MEETS 1
#define MIRAGE_C3RC_BOX_NEAR_FOLD 2

// Each fold interval's sweep is bounded piece by piece: thinner hulls keep fewer boxes (on
// concave-dish 8 pieces keep 12,759 leaves where one keeps 15,208; 11,962 without the folds).
#define MIRAGE_C3RC_FOLD_PIECES 8

SHARED_BEGIN

// The slack both culling stages give a box, so that rounding never culls a box that touches the
// view volume (the tests then only err on the side of keeping).
SHARED_FN float c3rc_box_margin(vec3 lo, vec3 hi) {
  return 1e-4f * length(hi - lo) + 1e-6f;
}

// The box lies entirely outside one of the C3RC's hull planes (C3rcData::hull).
SHARED_FN bool c3rc_hull_rejects(C3rcData c, vec3 lo, vec3 hi) {
  vec3 centre = 0.5f * (lo + hi), half_size = 0.5f * (hi - lo);
  float margin = c3rc_box_margin(lo, hi);
  for (int i = 0; i < c.counts.x; ++i) {
    vec3 a = vec3(c.hull[i]);
    float lowest = dot(a, centre) - dot(abs(a), half_size);
    if (lowest > c.hull[i].w + margin) return true;
  }
  return false;
}

// Every point within the box whose normal lies in `cone` (xyz the unit axis, w the cosine of the
// half-angle θ; w < −1: no cone) faces away from v, i.e. n·(v − q) < 0. With c the box's centre,
// r its half-diagonal and u = v − c, n·(v − q) ≤ n·u + r; over the cone the largest n·u is |u|
// when u lies within it, else |u| cos(φ − θ) = (a·u) cos θ + |u × a| sin θ (φ the angle of u to
// the axis a). The box is widened by the culling's margin and r by 1e-4 (|u| + r) for rounding.
SHARED_FN bool c3rc_cone_faces_away_from(vec4 cone, vec3 lo, vec3 hi, vec3 v) {
  float margin = c3rc_box_margin(lo, hi);
  vec3 u = v - 0.5f * (lo + hi);
  float r = 0.5f * length(hi - lo) + margin;
  float along = dot(vec3(cone), u), distance = length(u);
  if (!(along < cone.w * distance)) return false;  // u within the cone (or no cone)
  float across = sqrt(max(distance * distance - along * along, 0.0f));
  float sine = sqrt(max(1.0f - cone.w * cone.w, 0.0f));
  return along * cone.w + across * sine < -(r + 1e-4f * (distance + r));
}

// The same for all three of v0 v1 v2: every point of the box with a normal in the cone is one
// the splatting skips (hybrid_faces_away), so the culling drops the box.
SHARED_FN bool c3rc_cone_faces_away(vec4 cone, vec3 lo, vec3 hi, vec3 v0, vec3 v1, vec3 v2) {
  return c3rc_cone_faces_away_from(cone, lo, hi, v0) &&
         c3rc_cone_faces_away_from(cone, lo, hi, v1) && c3rc_cone_faces_away_from(cone, lo, hi, v2);
}

// The triangle's points p0 p1 p2 (relative to the box centre) all lie beyond the box's extent
// `half_size` along `axis`.
SHARED_FN bool c3rc_axis_separates(vec3 axis, vec3 half_size, vec3 p0, vec3 p1, vec3 p2) {
  float r = dot(abs(axis), half_size);
  float d0 = dot(axis, p0), d1 = dot(axis, p1), d2 = dot(axis, p2);
  return min(min(d0, d1), d2) > r || max(max(d0, d1), d2) < -r;
}

SHARED_FN bool c3rc_triangle_meets_box(vec3 a, vec3 b, vec3 c, vec3 lo, vec3 hi) {
  // Separating axes (Akenine-Möller): the box's 3 normals, the triangle's normal, and the 9
  // cross products of the triangle's edges with the box's axes.
  vec3 centre = 0.5f * (lo + hi), half_size = 0.5f * (hi - lo);
  vec3 p0 = a - centre, p1 = b - centre, p2 = c - centre;
  vec3 e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
  for (int i = 0; i < 3; ++i) {
    vec3 axis = vec3(0.0f);
    axis[i] = 1.0f;
    if (c3rc_axis_separates(axis, half_size, p0, p1, p2)) return false;
    if (c3rc_axis_separates(cross(e0, axis), half_size, p0, p1, p2)) return false;
    if (c3rc_axis_separates(cross(e1, axis), half_size, p0, p1, p2)) return false;
    if (c3rc_axis_separates(cross(e2, axis), half_size, p0, p1, p2)) return false;
  }
  return !c3rc_axis_separates(cross(e0, e1), half_size, p0, p1, p2);
}

// The ray origin + t dir, t ≥ 0, meets the box (slabs).
SHARED_FN bool c3rc_ray_meets_box(vec3 origin, vec3 dir, vec3 lo, vec3 hi) {
  float t0 = 0.0f, t1 = uintBitsToFloat(0x7F800000u);  // +infinity
  for (int i = 0; i < 3; ++i) {
    if (dir[i] == 0.0f) {
      if (origin[i] < lo[i] || origin[i] > hi[i]) return false;
      continue;
    }
    float a = (lo[i] - origin[i]) / dir[i], b = (hi[i] - origin[i]) / dir[i];
    t0 = max(t0, min(a, b));
    t1 = min(t1, max(a, b));
    if (t0 > t1) return false;
  }
  return true;
}

// The wall's rays are parallel to the edge p q (U = q − p, uu = |U|²): only the ray at the α where
// the wall's base edge meets the edge's line can touch it; then compare the two along that line.
SHARED_FN bool c3rc_parallel_wall_meets(vec3 A, vec3 E, vec3 D, vec3 F, vec3 U, float uu, float a1,
                                        float b1, float a2, float b2, float base_scale) {
  bool first = abs(b1) >= abs(b2);
  float b = first ? b1 : b2;
  if (abs(b) <= 1e-12f * base_scale) return abs(a1) + abs(a2) <= 1e-6f * base_scale;
  float alpha = -(first ? a1 : a2) / b;
  if (alpha < -1e-4f || alpha > 1.0f + 1e-4f) return false;
  if (abs(first ? a2 + b2 * alpha : a1 + b1 * alpha) > 1e-5f * base_scale) return false;
  float start = dot(A + alpha * E, U) / uu;  // the ray's origin along the edge
  float along = dot(D + alpha * F, U);       // its direction along the edge
  return along >= 0.0f ? start <= 1.0f + 1e-4f : start >= -1e-4f;
}

// The segment p q crosses the side wall S(α, λ) = vi + α(vj − vi) + λ(di + α(dj − di)),
// α ∈ [0, 1], λ ≥ 0 (with slack: conservative).
SHARED_FN bool c3rc_segment_crosses_wall(vec3 p, vec3 q, vec3 vi, vec3 vj, vec3 di, vec3 dj) {
  // Solve A + αE + λ(D + αF) = tU with A = vi − p, U = q − p: the components perpendicular to
  // U give two bilinear equations in (α, λ); eliminating λ leaves a quadratic in α.
  vec3 U = q - p;
  float uu = dot(U, U);
  if (!(uu > 0.0f)) return false;  // a zero-length edge: the other edges of the box cover it
  vec3 A = vi - p, E = vj - vi, D = di, F = dj - di;
  vec3 helper = abs(U.x) < abs(U.y) && abs(U.x) < abs(U.z)
                    ? vec3(1, 0, 0)
                    : (abs(U.y) < abs(U.z) ? vec3(0, 1, 0) : vec3(0, 0, 1));
  vec3 m1 = normalize(cross(U, helper));
  vec3 m2 = normalize(cross(U, m1));
  float a1 = dot(m1, A), b1 = dot(m1, E), c1 = dot(m1, D), e1 = dot(m1, F);
  float a2 = dot(m2, A), b2 = dot(m2, E), c2 = dot(m2, D), e2 = dot(m2, F);
  float qa = b1 * e2 - b2 * e1;
  float qb = a1 * e2 + b1 * c2 - a2 * e1 - b2 * c1;
  float qc = a1 * c2 - a2 * c1;
  float scale =
      (abs(a1) + abs(b1) + abs(a2) + abs(b2)) * (abs(c1) + abs(e1) + abs(c2) + abs(e2)) + 1e-30f;
  if (abs(qa) + abs(qb) + abs(qc) <= 1e-6f * scale) {
    float ray_scale = abs(c1) + abs(e1) + abs(c2) + abs(e2);
    float base_scale = abs(a1) + abs(b1) + abs(a2) + abs(b2) + 1e-30f;
    if (ray_scale > 1e-6f * (length(D) + length(F)))
      return true;  // the two equations agree along a curve: keep the box (conservative)
    return c3rc_parallel_wall_meets(A, E, D, F, U, uu, a1, b1, a2, b2, base_scale);
  }
  float r0 = 0.0f, r1 = 0.0f;
  int n = c3rc_quadratic_roots(qa, qb, qc, r0, r1);
  for (int i = 0; i < n; ++i) {
    float alpha = i == 0 ? r0 : r1;
    if (alpha < -1e-4f || alpha > 1.0f + 1e-4f) continue;
    float den1 = c1 + e1 * alpha, den2 = c2 + e2 * alpha;
    bool first = abs(den1) >= abs(den2);
    float den = first ? den1 : den2;
    if (abs(den) <= 1e-12f) return true;  // the ray at α is parallel: keep
    float lambda = -(first ? a1 + b1 * alpha : a2 + b2 * alpha) / den;
    if (lambda < -1e-4f) continue;
    vec3 x = A + alpha * E + lambda * (D + alpha * F);
    float t = dot(x, U) / uu;
    if (t >= -1e-4f && t <= 1.0f + 1e-4f) return true;
  }
  return false;
}

// The six points a0 a1 a2 b0 b1 b2 (relative to the box centre) all lie beyond the box's extent
// `half_size` along `axis`.
SHARED_FN bool c3rc_axis_separates6(vec3 axis, vec3 half_size, vec3 a0, vec3 a1, vec3 a2, vec3 b0,
                                    vec3 b1, vec3 b2) {
  float r = dot(abs(axis), half_size);
  float da0 = dot(axis, a0), da1 = dot(axis, a1), da2 = dot(axis, a2);
  float db0 = dot(axis, b0), db1 = dot(axis, b1), db2 = dot(axis, b2);
  float lowest = min(min(min(da0, da1), min(da2, db0)), min(db1, db2));
  float highest = max(max(max(da0, da1), max(da2, db0)), max(db1, db2));
  return lowest > r || highest < -r;
}

// The box may meet the sweep of the base over [la, lb]: every T(λ) there lies in the convex hull
// of T(la) and T(lb) (each vertex v_k + λ d_k runs along the segment between its two ends), and
// the box is kept unless one of these axes separates it from the hull's six corners: the box's
// normals, the two triangles' normals, and the box's axes crossed with the rays and with the two
// triangles' edges. A separating axis of the six corners separates their hull (it is the
// projection's extremes that are compared), so a box this rejects misses every T(λ).
SHARED_FN bool c3rc_sweep_may_meet_box(C3rcData c, float la, float lb, vec3 lo, vec3 hi) {
  vec3 centre = 0.5f * (lo + hi), half_size = 0.5f * (hi - lo);
  vec3 d0 = vec3(c.d0), d1 = vec3(c.d1), d2 = vec3(c.d2);
  vec3 a0 = vec3(c.v0) + la * d0 - centre, a1 = vec3(c.v1) + la * d1 - centre;
  vec3 a2 = vec3(c.v2) + la * d2 - centre;
  vec3 b0 = vec3(c.v0) + lb * d0 - centre, b1 = vec3(c.v1) + lb * d1 - centre;
  vec3 b2 = vec3(c.v2) + lb * d2 - centre;
  if (c3rc_axis_separates6(cross(a1 - a0, a2 - a0), half_size, a0, a1, a2, b0, b1, b2) ||
      c3rc_axis_separates6(cross(b1 - b0, b2 - b0), half_size, a0, a1, a2, b0, b1, b2))
    return false;
  for (int i = 0; i < 3; ++i) {
    vec3 axis = vec3(0.0f);
    axis[i] = 1.0f;
    if (c3rc_axis_separates6(axis, half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(d0, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(d1, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(d2, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(a1 - a0, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(a2 - a1, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(a0 - a2, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(b1 - b0, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(b2 - b1, axis), half_size, a0, a1, a2, b0, b1, b2) ||
        c3rc_axis_separates6(cross(b0 - b2, axis), half_size, a0, a1, a2, b0, b1, b2))
      return false;
  }
  return true;
}

// The box may meet the sweep over one of the C3RC's fold intervals (C3rcData::folds), widened by
// a little for the rounding of the sidedness roots, in MIRAGE_C3RC_FOLD_PIECES pieces of λ.
SHARED_FN bool c3rc_fold_interval_may_meet_box(C3rcData c, float start, float end, vec3 lo,
                                               vec3 hi) {
  if (start > end) return false;
  float slack = 1e-4f * (1.0f + end);
  float a = max(start - slack, 0.0f), b = min(end + slack, c.info.w);
  for (int i = 0; i < MIRAGE_C3RC_FOLD_PIECES; ++i) {
    float from = mix(a, b, float(i) / float(MIRAGE_C3RC_FOLD_PIECES));
    float to = mix(a, b, float(i + 1) / float(MIRAGE_C3RC_FOLD_PIECES));
    if (c3rc_sweep_may_meet_box(c, from, to, lo, hi)) return true;
  }
  return false;
}

// A box no boundary test finds may still meet a fold surface of the view volume: the sweep of
// either fold interval holds it (c3rc_cull.h).
SHARED_FN bool c3rc_fold_may_meet_box(C3rcData c, vec3 lo, vec3 hi) {
  return c3rc_fold_interval_may_meet_box(c, c.folds.x, c.folds.y, lo, hi) ||
         c3rc_fold_interval_may_meet_box(c, c.folds.z, c.folds.w, lo, hi);
}

// The box's 12 edges cross one of the 3 side walls.
SHARED_FN bool c3rc_box_edges_cross_walls(C3rcData c, vec3 lo, vec3 hi) {
  vec3 v0 = vec3(c.v0), v1 = vec3(c.v1), v2 = vec3(c.v2);
  vec3 d0 = vec3(c.d0), d1 = vec3(c.d1), d2 = vec3(c.d2);
  for (int axis = 0; axis < 3; ++axis) {
    int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      vec3 from = lo;
      from[u] = (corner & 1) != 0 ? hi[u] : lo[u];
      from[w] = (corner & 2) != 0 ? hi[w] : lo[w];
      vec3 to = from;
      to[axis] = hi[axis];
      if (c3rc_segment_crosses_wall(from, to, v0, v1, d0, d1) ||
          c3rc_segment_crosses_wall(from, to, v1, v2, d1, d2) ||
          c3rc_segment_crosses_wall(from, to, v2, v0, d2, d0))
        return true;
    }
  }
  return false;
}

// The exact (conservative) test, MIRAGE_C3RC_BOX_*: OUT only when the box and the view volume
// are disjoint. The cases in the order of c3rc_cull.h's proof, cheapest first.
SHARED_FN int c3rc_classify_box(C3rcData c, vec3 box_lo, vec3 box_hi) {
  float margin = c3rc_box_margin(box_lo, box_hi);
  vec3 lo = box_lo - vec3(margin), hi = box_hi + vec3(margin);
  vec3 v0 = vec3(c.v0), v1 = vec3(c.v1), v2 = vec3(c.v2);
  vec3 d0 = vec3(c.d0), d1 = vec3(c.d1), d2 = vec3(c.d2);
  float far = c.info.w;
  // Inside: one corner projects (every corner does when the box is inside).
  vec4 p0, p1, p2;
  if (c3rc_project(c, lo, 1e-4f, true, p0, p1, p2) > 0 ||
      c3rc_triangle_meets_box(v0, v1, v2, lo, hi) || c3rc_ray_meets_box(v0, d0, lo, hi) ||
      c3rc_ray_meets_box(v1, d1, lo, hi) || c3rc_ray_meets_box(v2, d2, lo, hi) ||
      c3rc_box_edges_cross_walls(c, lo, hi) ||
      c3rc_triangle_meets_box(v0 + far * d0, v1 + far * d1, v2 + far * d2, lo, hi))
    return MIRAGE_C3RC_BOX_MEETS;
  return c3rc_fold_may_meet_box(c, lo, hi) ? MIRAGE_C3RC_BOX_NEAR_FOLD : MIRAGE_C3RC_BOX_OUT;
}

SHARED_FN bool c3rc_box_meets_view_volume(C3rcData c, vec3 box_lo, vec3 box_hi) {
  return c3rc_classify_box(c, box_lo, box_hi) != MIRAGE_C3RC_BOX_OUT;
}

SHARED_END

#endif  // MIRAGE_METHODS_HYBRID_C3RC_CULL_SHARED_H
