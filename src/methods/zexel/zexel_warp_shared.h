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

// The depth over the plane distance of a zexel that saw nothing (δ = 0: a direction, warped by
// P_o⁻¹ P_i alone, infinitely far in every image).
SHARED_CONST float ZEXEL_AT_INFINITY = 3.0e38f;

// (u_o, v_o, w): the pixel the zexel lands on and w = Z_o / n_o, its depth in the output image
// over that image's plane distance (w <= 0: behind the output camera, not drawn; δ = 0: w is
// ZEXEL_AT_INFINITY when the direction is in front of the output camera).
SHARED_FN vec3 zexel_warp(mat3 po_inverse, mat3 pi, vec3 ci, vec3 co, float delta, vec2 xi) {
  vec3 xo = delta * (po_inverse * (ci - co)) + po_inverse * (pi * vec3(xi, 1.0f));
  float w = delta > 0.0f ? xo.z / delta : (xo.z > 0.0f ? ZEXEL_AT_INFINITY : -1.0f);
  return vec3(xo.x / xo.z, xo.y / xo.z, w);
}

// The side of the square splat that closes the gaps between a zexel and its neighbours in the
// output: the warp's local magnification, the landing points of x_i + (1, 0) and x_i + (0, 1)
// at the same disparity (a surface facing the reference camera), rounded up to whole output
// pixels of `unit` frame pixels each (--ssaa: a supersampled frame's splats cover what the native
// frame's do), within [unit, largest].
SHARED_FN int zexel_splat_side(mat3 po_inverse, mat3 pi, vec3 ci, vec3 co, float delta, vec2 xi,
                               vec2 landed, int largest, int unit) {
  vec3 right = zexel_warp(po_inverse, pi, ci, co, delta, xi + vec2(1.0f, 0.0f));
  vec3 up = zexel_warp(po_inverse, pi, ci, co, delta, xi + vec2(0.0f, 1.0f));
  float spread = max(max(abs(right.x - landed.x), abs(right.y - landed.y)),
                     max(abs(up.x - landed.x), abs(up.y - landed.y)));
  // Non-finite (a neighbour behind the camera) or huge: the largest splat.
  if (!(spread < float(largest))) return largest;
  return clamp(int(ceil(spread / float(unit))) * unit, unit, largest);
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
