// Method `ssr`: window depth and view depth, shared by the pyramid's build, the march and the
// tests. A surface of the depth buffer is taken to be `thickness` thick (view-depth units): a
// ray entering a pixel behind it by no more than that hits it. The pyramid stores, beside each
// cell's nearest depth, the window depth of its farthest surface's back — its "behind limit" —
// so that the march tests a ray against the thickness with one comparison, no division.
#ifndef MIRAGE_METHODS_SSR_SSR_DEPTH_SHARED_H
#define MIRAGE_METHODS_SSR_SSR_DEPTH_SHARED_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// View depth (distance along the view axis) of window depth `z` under a perspective projection
// with planes `near_plane`, `far_plane` (OpenGL clip space, depth range 0..1).
SHARED_FN float ssr_view_depth(float z, float near_plane, float far_plane) {
  float ndc = 2.0f * z - 1.0f;
  return 2.0f * near_plane * far_plane /
         ((far_plane + near_plane) - ndc * (far_plane - near_plane));
}

// Its inverse: the window depth of view depth `v` (above 1 past the far plane).
SHARED_FN float ssr_window_depth(float v, float near_plane, float far_plane) {
  float ndc =
      ((far_plane + near_plane) - 2.0f * near_plane * far_plane / v) / (far_plane - near_plane);
  return 0.5f * ndc + 0.5f;
}

// The behind limit of depth `d`: the window depth `thickness` behind it in view depth, so that
// a ray at window depth z is behind the surface by more than the thickness exactly when
// z > limit (view depth grows with window depth). 0 where nothing is drawn (d >= 1): every ray
// is "behind" nothing, and the maximum over a cell is its farthest surface's limit.
SHARED_FN float ssr_behind_limit(float d, float thickness, float near_plane, float far_plane) {
  if (d >= 1.0f) return 0.0f;
  return ssr_window_depth(ssr_view_depth(d, near_plane, far_plane) + thickness, near_plane,
                          far_plane);
}

SHARED_END

#endif  // MIRAGE_METHODS_SSR_SSR_DEPTH_SHARED_H
