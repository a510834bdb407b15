// McMillan's forward 3-D warp of a zexel (the forward-mapped planar mirror paper, eq. 3), shared
// by the warping shader and the C++ code and tests.
//
// An image's pixel matrix P maps window coordinates (u, v, 1) (origin bottom-left, pixel centres
// at +0.5) to the ray through that pixel, scaled so that its component along the view axis is
// the image plane's distance n (the near distance): a point seen at pixel x at eye depth Z is
// c + (Z / n) P x, and its disparity is δ = n / Z (eq. 4's 1 − z (far − near) / far for the
// classic GL depth z). The warp of zexel x_i of reference image (c_i, P_i) into image (c_o, P_o):
//     x_o = δ P_o⁻¹ (c_i − c_o) + P_o⁻¹ P_i x_i        (homogeneous: divide by its third)
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_WARP_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_WARP_SHARED_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// (u_o, v_o, w): the pixel the zexel lands on and w = Z_o / n_o, its depth in the output image
// over that image's plane distance (w <= 0: behind the output camera, not drawn).
SHARED_FN vec3 zexel_warp(mat3 po_inverse, mat3 pi, vec3 ci, vec3 co, float delta, vec2 xi) {
  vec3 xo = delta * (po_inverse * (ci - co)) + po_inverse * (pi * vec3(xi, 1.0f));
  return vec3(xo.x / xo.z, xo.y / xo.z, xo.z / delta);
}

// Eq. 4: the disparity from the classic [0, 1] GL depth of a perspective camera.
SHARED_FN float zexel_disparity_from_depth(float z, float near_plane, float far_plane) {
  return 1.0f - z * (far_plane - near_plane) / far_plane;
}

// The same from the distance along the pixel's ray (what the maps store: their oblique near
// plane at the mirror makes their GL depth non-classic): n / Z = |P x| / distance.
SHARED_FN float zexel_disparity_from_distance(mat3 p, vec2 x, float distance) {
  return length(p * vec3(x, 1.0f)) / distance;
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_WARP_SHARED_H
