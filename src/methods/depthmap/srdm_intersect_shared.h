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

// The paper's search (§4.3 steps 4-5): the row through the projected ray's midpoint.
SHARED_FN float srdm_intersect(vec3 from, vec3 to, int n, int w, int m) {
  return srdm_intersect_at(from, to, n, w, m, 0.5f);
}

// Two rows (our answer to the paper's §5.2 "lookup the two best rows"): the row through the
// midpoint stands for the whole ray, and is off the ray by up to half the ray's length times
// the angle to the nearest domain; where it finds a hit, the row through that hit is the best
// row there, so its answer replaces the first one's.
SHARED_FN float srdm_intersect_two_rows(vec3 from, vec3 to, int n, int w, int m) {
  float first = srdm_intersect_at(from, to, n, w, m, 0.5f);
  if (first < 0.0f) return first;
  return srdm_intersect_at(from, to, n, w, m, first);
}

SHARED_END

#endif  // MIRAGE_METHODS_DEPTHMAP_SRDM_INTERSECT_SHARED_H
