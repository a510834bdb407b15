// The ray-SRDM intersection (the impostor paper, §4.3, steps 4-5), shared by the depth-map
// shader and the C++ code. It reads the rows through a function that the includer defines
// before including this file (GLSL: a texelFetch of the SRDM array; C++: srdm.cpp):
//   vec4 srdm_point_pair(int domain, int row, int pair);  // points 2 pair and 2 pair + 1
#ifndef MIRAGE_METHODS_DEPTHMAP_SRDM_INTERSECT_SHARED_H
#define MIRAGE_METHODS_DEPTHMAP_SRDM_INTERSECT_SHARED_H

#include "methods/depthmap/srdm_shared.h"

SHARED_BEGIN

// Where a ray, projected to the row as the segment (s0, d0) -> (s1, d1), first crosses the row's
// polyline from in front (smaller d) to behind, walking the polyline in the ray's order; a
// crossing counts only inside a span (gaps between spans are never hit) and only where the ray
// passes from in front to behind (a ray that enters a span already behind it passes behind the
// object). Returns the fraction lambda in [0, 1] of the way from (s0, d0) to (s1, d1), or -1.
SHARED_FN float srdm_row_crossing(int domain, int row, int m, vec2 from, vec2 to) {
  const float eps = 1.0e-6f;
  bool forward = to.x >= from.x;
  float s_lo = min(from.x, to.x), s_hi = max(from.x, to.x);
  float ds = to.x - from.x;
  bool degenerate = abs(ds) < eps;  // the ray projects to (almost) a point of the row
  int pairs = (m + 1) / 2;
  float best = -1.0f;
  // The ray's order: forward walks segments left to right and takes the first crossing;
  // backward takes the last one found (the first along the ray). Both visit every segment, so
  // that the loop has a fixed trip count (llvmpipe runs every lane to the longest anyway).
  vec2 prev = vec2(-1.0f, 1.0f);
  for (int pair = 0; pair < pairs; ++pair) {
    vec4 two = srdm_point_pair(domain, row, pair);
    for (int half_index = 0; half_index < 2; ++half_index) {
      vec2 point = half_index == 0 ? vec2(two.x, two.y) : vec2(two.z, two.w);
      bool starts_span = point.x < 0.0f;
      vec2 cur = vec2(abs(point.x), point.y);
      bool first_point = pair == 0 && half_index == 0;
      bool solid = !first_point && !starts_span && cur.x > prev.x;
      if (solid) {
        float lo = max(prev.x, s_lo), hi = min(cur.x, s_hi);
        if (degenerate) {
          if (from.x >= prev.x && from.x <= cur.x) {
            float dp = mix(prev.y, cur.y, (from.x - prev.x) / (cur.x - prev.x));
            float dd = to.y - from.y;
            // In front at the start, behind at the end: the crossing is where d = dp.
            if (from.y < dp && to.y >= dp && best < 0.0f)
              best = abs(dd) > eps ? (dp - from.y) / dd : 0.0f;
          }
        } else if (lo <= hi) {
          // f = ray depth - polyline depth at both ends of the overlap, in the ray's order.
          float slope = (cur.y - prev.y) / (cur.x - prev.x);
          float s_a = forward ? lo : hi, s_b = forward ? hi : lo;
          float f_a = mix(from.y, to.y, (s_a - from.x) / ds) - (prev.y + (s_a - prev.x) * slope);
          float f_b = mix(from.y, to.y, (s_b - from.x) / ds) - (prev.y + (s_b - prev.x) * slope);
          if (f_a < 0.0f && f_b >= 0.0f) {
            float s_hit = s_a + (s_b - s_a) * (-f_a / (f_b - f_a));
            float lambda = clamp((s_hit - from.x) / ds, 0.0f, 1.0f);
            // Forward: the first found is the first along the ray; backward: the last found.
            if (!forward || best < 0.0f) best = lambda;
          }
        }
      }
      prev = cur;
    }
  }
  return best;
}

// The first crossing of the depth map by a ray whose clipped projection runs from `from` to `to`
// in (x, y, d) texel space, searched in the row that contains the projected ray's point at the
// fraction `at` of the way, of the domain in which the projection is closest to horizontal.
// Returns the fraction lambda of the way from `from` to `to`, or -1 on a miss.
SHARED_FN float srdm_intersect_at(vec3 from, vec3 to, int n, int w, int m, float at) {
  vec2 along = vec2(to.x - from.x, to.y - from.y);
  int domain = dot(along, along) > 1.0e-12f ? srdm_domain_of(along, n) : 0;
  float theta = srdm_theta(domain, n);
  vec2 a = srdm_to_domain(vec2(from.x, from.y), theta, float(w));
  vec2 b = srdm_to_domain(vec2(to.x, to.y), theta, float(w));
  int row = srdm_row_of(a.y + (b.y - a.y) * at, theta, w);
  if (row < 0) return -1.0f;
  return srdm_row_crossing(domain, row, m, vec2(a.x, from.z), vec2(b.x, to.z));
}

// A row seen along the ray, for the interpolated search: the row's point k (0..m-1) in the ray's
// order (reversed when the ray runs towards smaller s) as (lambda, depth, starts): lambda the
// fraction of the way along the ray's projection, s0 + lambda (s1 - s0) = s, and starts 1 when
// the point starts a span in the row's own order.
SHARED_FN vec3 srdm_ray_point(int domain, int row, int m, bool forward, float s0, float inv_ds,
                              int k) {
  int index = forward ? k : m - 1 - k;
  vec4 two = srdm_point_pair(domain, row, index / 2);
  vec2 p = index - 2 * (index / 2) == 0 ? vec2(two.x, two.y) : vec2(two.z, two.w);
  return vec3((abs(p.x) - s0) * inv_ds, p.y, p.x < 0.0f ? 1.0f : 0.0f);
}

// Moves a row's cursor to its next segment in the ray's order. seg: the segment's ends
// (lambda0, depth0, lambda1, depth1); state: x the next point, y 1 when the segment lies inside
// a span, z the starts flag of the segment's end. Past the last point the segment is a gap that
// runs to lambda = 3e38.
SHARED_FN void srdm_ray_advance(int domain, int row, int m, bool forward, float s0, float inv_ds,
                                SHARED_INOUT(vec4) seg, SHARED_INOUT(ivec3) state) {
  bool left_starts = state.z != 0;
  seg = vec4(seg.z, seg.w, 3.0e38f, 1.0f);
  state.y = 0;
  if (state.x >= m) return;
  vec3 p = srdm_ray_point(domain, row, m, forward, s0, inv_ds, state.x);
  state.x += 1;
  // In the row's order the segment into a point is a gap when the point starts a span; walked
  // backwards, that is the flag of the point just left.
  bool gap = forward ? p.z > 0.5f : left_starts;
  state.y = (state.x > 1 && !gap && p.x > seg.x) ? 1 : 0;
  state.z = p.z > 0.5f ? 1 : 0;
  seg = vec4(seg.x, seg.y, p.x, p.y);
}

// The depth of a cursor's segment at lambda (inside it).
SHARED_FN float srdm_ray_depth(vec4 seg, float lambda) {
  return seg.y + (seg.w - seg.y) * (lambda - seg.x) / max(seg.z - seg.x, 1.0e-30f);
}

// The first crossing from in front to behind of the ray (depth z0 -> z1 over lambda 0 -> 1) with
// the blend of two rows, a with weight w_a and b with 1 - w_a, each given by its domain, row and
// the ray's ends s0 -> s1 along it. Where both rows are inside a span the surface is the
// weighted depth; where one is, the surface is that row's if it is the nearer (weight >= 1/2)
// and nothing otherwise, so that silhouettes stay the nearer row's, as with one row. Both rows'
// points are merged in lambda order: at most 2m pieces, each linear in lambda.
SHARED_FN float srdm_blend_crossing(int domain_a, int row_a, vec2 s_a, int domain_b, int row_b,
                                    vec2 s_b, float w_a, int m, float z0, float z1) {
  bool fa = s_a.y >= s_a.x, fb = s_b.y >= s_b.x;
  float ia = 1.0f / (s_a.y - s_a.x), ib = 1.0f / (s_b.y - s_b.x);
  vec4 sa = vec4(-3.0e38f, 1.0f, -3.0e38f, 1.0f), sb = sa;
  ivec3 ca = ivec3(0), cb = ivec3(0);
  srdm_ray_advance(domain_a, row_a, m, fa, s_a.x, ia, sa, ca);
  srdm_ray_advance(domain_b, row_b, m, fb, s_b.x, ib, sb, cb);
  float lo = 0.0f;
  for (int piece = 0; piece <= 2 * m; ++piece) {
    float hi = min(min(sa.z, sb.z), 1.0f);
    bool in_a = ca.y != 0, in_b = cb.y != 0;
    bool surface = (in_a && (in_b || w_a >= 0.5f)) || (in_b && w_a < 0.5f);
    if (surface && hi > lo) {
      float wa = in_a ? (in_b ? w_a : 1.0f) : 0.0f;
      float da_lo = in_a ? srdm_ray_depth(sa, lo) : 0.0f,
            da_hi = in_a ? srdm_ray_depth(sa, hi) : 0.0f;
      float db_lo = in_b ? srdm_ray_depth(sb, lo) : 0.0f,
            db_hi = in_b ? srdm_ray_depth(sb, hi) : 0.0f;
      float f_lo = z0 + (z1 - z0) * lo - (wa * da_lo + (1.0f - wa) * db_lo);
      float f_hi = z0 + (z1 - z0) * hi - (wa * da_hi + (1.0f - wa) * db_hi);
      if (f_lo < 0.0f && f_hi >= 0.0f) return lo + (hi - lo) * (-f_lo / (f_hi - f_lo));
    }
    lo = max(lo, hi);
    if (lo >= 1.0f) break;
    bool move_a = sa.z <= hi, move_b = sb.z <= hi;
    if (move_a) srdm_ray_advance(domain_a, row_a, m, fa, s_a.x, ia, sa, ca);
    if (move_b) srdm_ray_advance(domain_b, row_b, m, fb, s_b.x, ib, sb, cb);
  }
  return -1.0f;
}

// Two rows interpolated: the paper's §5.2 ("lookup the two best rows and interpolate", against
// the edge artifacts of large angular increments). The two best rows for the ray at the
// fraction `at` of its projection are the rows through that point in the two domains whose
// angles bracket the ray's direction; they cross near it, and the ray lies between them at the
// fraction of the angle that separates it from each, so their depths are blended with weights
// linear in that angle (the nearer domain's weight is 1/2 to 1). A projection shorter than a
// texel, or a second row outside the map, is searched in the nearer row alone.
SHARED_FN float srdm_intersect_interpolated_at(vec3 from, vec3 to, int n, int w, int m, float at) {
  vec2 along = vec2(to.x - from.x, to.y - from.y);
  if (n < 2 || dot(along, along) < 1.0f) return srdm_intersect_at(from, to, n, w, m, at);
  float angle = atan(along.y, along.x);
  if (angle < 0.0f) angle += MIRAGE_SRDM_PI;
  float steps = angle / (MIRAGE_SRDM_PI / float(n));
  int near_domain = int(floor(steps + 0.5f));
  float off = steps - float(near_domain);  // -1/2 .. 1/2 domains from the nearer one
  int far_domain = off >= 0.0f ? near_domain + 1 : near_domain - 1;
  near_domain = near_domain >= n ? near_domain - n : near_domain;
  far_domain = far_domain >= n ? far_domain - n : (far_domain < 0 ? far_domain + n : far_domain);
  float theta_a = srdm_theta(near_domain, n), theta_b = srdm_theta(far_domain, n);
  vec2 a0 = srdm_to_domain(vec2(from.x, from.y), theta_a, float(w));
  vec2 a1 = srdm_to_domain(vec2(to.x, to.y), theta_a, float(w));
  vec2 b0 = srdm_to_domain(vec2(from.x, from.y), theta_b, float(w));
  vec2 b1 = srdm_to_domain(vec2(to.x, to.y), theta_b, float(w));
  int row_a = srdm_row_of(a0.y + (a1.y - a0.y) * at, theta_a, w);
  int row_b = srdm_row_of(b0.y + (b1.y - b0.y) * at, theta_b, w);
  if (row_a < 0) return -1.0f;
  if (row_b < 0 || abs(b1.x - b0.x) < 1.0e-3f || abs(a1.x - a0.x) < 1.0e-3f)
    return srdm_row_crossing(near_domain, row_a, m, vec2(a0.x, from.z), vec2(a1.x, to.z));
  return srdm_blend_crossing(near_domain, row_a, vec2(a0.x, a1.x), far_domain, row_b,
                             vec2(b0.x, b1.x), 1.0f - abs(off), m, from.z, to.z);
}

// The searches, through the point at fraction `at` of the projected ray: its row, or with
// `interpolate` the two best rows there, interpolated (--srdm-second interpolate). The paper's
// search (§4.3 steps 4-5) is the one row through the midpoint. The midpoint's row stands for the
// whole ray, and is off the ray by up to half the ray's length times the angle to the nearest
// domain: with `hit_first` (--srdm-second hit and hit-interpolate, our answer to the paper's
// §5.2 "lookup the two best rows") the midpoint's row finds where the ray meets the surface, and
// the search through that point answers instead (a miss stays a miss; two or three rows read).
SHARED_FN float srdm_search(vec3 from, vec3 to, int n, int w, int m, bool hit_first,
                            bool interpolate) {
  float at = 0.5f;
  if (hit_first) {
    at = srdm_intersect_at(from, to, n, w, m, 0.5f);
    if (at < 0.0f) return at;
  }
  return interpolate ? srdm_intersect_interpolated_at(from, to, n, w, m, at)
                     : srdm_intersect_at(from, to, n, w, m, at);
}

SHARED_END

#endif  // MIRAGE_METHODS_DEPTHMAP_SRDM_INTERSECT_SHARED_H
