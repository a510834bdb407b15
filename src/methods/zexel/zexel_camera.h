// The cameras of the zexel method: an image's pixel matrix (zexel_warp_shared.h) and the reference
// camera that captures a mirror's depth-preserving reflection map.
#pragma once

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

}  // namespace mirage
