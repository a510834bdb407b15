// The cameras of the zexel method: an image's pixel matrix (zexel_warp_shared.h) and the reference
// camera that captures a mirror's depth-preserving reflection map.
#pragma once

#include <vector>

#include "core/camera.h"

namespace mirage {

// P of `view`: window coordinates (u, v, 1) to the ray through that pixel, its component along
// the view axis `plane_distance`.
mat3 zexelPixelMatrix(const View& view, float plane_distance);

// The reference camera of a mirror (centre `point`, unit `normal` towards the scene it reflects,
// `half_diagonal` its half-diagonal): at the pole of the hemisphere behind it, on its axis at a
// distance of the half-diagonal (the mirror spans 90° diagonally), looking through it with a
// vertical field of view `fov_y_degrees`, `size` texels square, the mirror plane as the near
// plane (nothing behind the mirror is captured).
View zexelReferenceView(const vec3& point, const vec3& normal, float half_diagonal, int size,
                        float fov_y_degrees);

// Where the reference cameras of a mirror stand: `count` unit directions w on the hemisphere
// behind it, in the mirror's frame (z: the unit normal), a camera at point − r·w looking along w.
// One map: the pole (z). More: a Fibonacci spiral over the spherical cap within `cone_degrees` of
// the pole, equal areas per camera (the paper's "regular sampling around a hemisphere").
std::vector<vec3> zexelHemisphere(int count, float cone_degrees);

// The reference camera at direction `w` (world space, w·normal > 0) of the hemisphere: as
// zexelReferenceView, but from point − half_diagonal·w looking at the mirror's centre.
View zexelHemisphereView(const vec3& point, const vec3& normal, const vec3& w, float half_diagonal,
                         int size, float fov_y_degrees);

// The `count` reference directions nearest (by angle) the direction from the mirrored eye to the
// mirror's centre, nearest first: the maps a frame warps.
std::vector<int> nearestZexelMaps(const std::vector<vec3>& directions, const vec3& point,
                                  const vec3& mirrored_eye, int count);

// The world-space frame of a mirror: x, y in its plane, z its unit normal.
mat3 zexelMirrorFrame(const vec3& normal);

}  // namespace mirage
