// Simplified rotated depth maps (SRDMs) as the shaders and the C++ code see them: section 4 of
// *Reflected-Scene Impostors for Realistic Reflections at Interactive Rates*. One copy of this
// code runs in the depth-map fragment shader, in the GPU builder and in the C++ builder and
// tests.
//
// Coordinates. A depth map is w x w texels of normalised depth d in [0, 1] (the GL window depth
// of its pinhole camera, affine in 1/z, so that a 3-D line projects to a straight line in
// (x, y, d)); x, y are texel units, texel (i, j) covering [i, i + 1] x [j, j + 1]; d = 1 is
// background. Rotated domain i (0 <= i < n) has the angle theta_i = pi i / n, the row direction
// a = (cos, sin) and the across direction b = (-sin, cos). Its rows cover the whole map at that
// angle: the map's extent along a and along b is E = w (|cos| + |sin|) (w sqrt 2 on the
// diagonal), centred on the map's centre; row j of w lies at t_j = (j + 0.5) E / w - E / 2
// across, and a point at s along it (0 <= s <= E) is centre + (s - E / 2) a + t_j b.
//
// Storage. Each row is a polyline of m points (s, d) with s increasing, two points per RGBA32F
// texel (xy, zw), in a 2-D array texture: x = point pair, y = row, layer = domain. A point whose
// stored s is negative (-s) starts a span: the segment that ends at it is a gap between spans
// and is never hit. Rows with fewer points repeat their last point as span starts (gaps).
#ifndef MIRAGE_METHODS_DEPTHMAP_SRDM_SHARED_H
#define MIRAGE_METHODS_DEPTHMAP_SRDM_SHARED_H

#include "shading/glsl_compat.h"

#define MIRAGE_SRDM_PI 3.14159265358979f

SHARED_BEGIN

// The extent E of the map along and across domain theta.
SHARED_FN float srdm_extent(float theta, float w) {
  return w * (abs(cos(theta)) + abs(sin(theta)));
}

SHARED_FN float srdm_theta(int domain, int n) {
  return MIRAGE_SRDM_PI * float(domain) / float(n);
}

// The domain in which a 2-D direction is closest to horizontal (along a): the nearest theta_i to
// the direction's angle modulo pi.
SHARED_FN int srdm_domain_of(vec2 direction, int n) {
  float angle = atan(direction.y, direction.x);  // (-pi, pi]
  if (angle < 0.0f) angle += MIRAGE_SRDM_PI;
  int i = int(floor(angle / (MIRAGE_SRDM_PI / float(n)) + 0.5f));
  return i >= n ? i - n : i;
}

// (s, t) of texel-space point p in domain theta: along and across, s from the row start.
SHARED_FN vec2 srdm_to_domain(vec2 p, float theta, float w) {
  vec2 a = vec2(cos(theta), sin(theta));
  vec2 b = vec2(-a.y, a.x);
  vec2 q = p - vec2(0.5f * w);
  return vec2(dot(q, a) + 0.5f * srdm_extent(theta, w), dot(q, b));
}

// The texel-space point at (s, t) of domain theta.
SHARED_FN vec2 srdm_from_domain(vec2 st, float theta, float w) {
  vec2 a = vec2(cos(theta), sin(theta));
  vec2 b = vec2(-a.y, a.x);
  return vec2(0.5f * w) + (st.x - 0.5f * srdm_extent(theta, w)) * a + st.y * b;
}

// The row (0..w-1) nearest to across-coordinate t, or -1 outside the domain.
SHARED_FN int srdm_row_of(float t, float theta, int w) {
  float extent = srdm_extent(theta, float(w));
  float j = floor((t + 0.5f * extent) * float(w) / extent);
  return (j < 0.0f || j >= float(w)) ? -1 : int(j);
}

SHARED_FN float srdm_row_t(int row, float theta, int w) {
  float extent = srdm_extent(theta, float(w));
  return (float(row) + 0.5f) * extent / float(w) - 0.5f * extent;
}

SHARED_END

#endif  // MIRAGE_METHODS_DEPTHMAP_SRDM_SHARED_H
