// For the tests and the benchmarks: a pinhole camera framing a bounding sphere as a depth-map
// impostor's does (the impostor paper, §4.1: "pphc"; the method's own is depthMapView), with
// near and far planes that enclose the sphere, so that the whole object lies in the depth range;
// and the depth map it sees, ray-traced on the CPU (the reference the GPU capture is checked
// against, and the input of the builder's benchmarks). Here, not in the depthmap room, so that
// the method's code names no raytrace/ header.
#pragma once

#include "core/camera.h"
#include "methods/depthmap/srdm.h"
#include "scene/scene.h"

namespace mirage {

// A square view of the sphere (centre, radius) from `from_direction` (towards the camera), its
// planes at distance -+ radius around the centre (near at least 1e-3 of the distance).
View depthCamera(const vec3& centre, float radius, const vec3& from_direction, float fov_y_degrees,
                 int size);

// The depth map of one instance of `scene` at `time` through `camera`: GL window depth of the
// nearest hit on that instance per texel centre (texel rows bottom-up, as GL reads them back);
// background (1) where the ray misses it or leaves the depth range.
DepthMap traceDepthMap(const Scene& scene, int instance, float time, const View& camera);

}  // namespace mirage
