// Analytic depth maps for the SRDM tests: spheres seen by a pinhole camera, ray-cast exactly.
#pragma once

#include <vector>

#include "methods/depthmap/srdm.h"

namespace mirage::test {

// Spheres (xyz centre, w radius) seen by a pinhole camera at the origin looking down -z
// (vertical and horizontal field of view 40 degrees): GL depth of the nearest hit per texel
// centre, 1 (background) where there is none or it lies outside [near, far].
DepthMap spheresDepthMap(int size, const std::vector<vec4>& spheres, float near = 1.0f,
                         float far = 5.0f);

// A large sphere with a smaller one in front of its edge and one behind: spans, silhouettes, a
// depth step.
DepthMap threeSpheresDepthMap(int size);

}  // namespace mirage::test
