// Which objects get depth-map impostors and where their cameras stand (the impostor paper, §4.1
// and §4.3). Every non-planar diffuse object gets `maps` depth maps (planar ones stay exact
// billboards). The cameras are fixed in the object's space — placed once, from the scene at
// time 0 — and move rigidly with it, so that an object's depth maps and SRDMs never need a
// rebuild when it moves (§4.3: "the DM camera is simply transformed").
//
// Map 0 looks at the object from the reflectors' centroid; map 1 from the opposite side (the
// front map the paper's swapping bunnies need); maps 2-5 from the four directions
// perpendicular to that axis. A ray uses the map whose camera looks most nearly along it.
//
// Self-reflections (the paper's §6 open problem: a concave reflector, the bunny's ears, reflects
// itself): with `self_maps` > 0, every non-planar reflector also gets that many maps of itself,
// storing its normal instead of a colour; rays leaving a reflector search its own maps and
// reflect off what they hit. Their axis is the scene camera's direction to the reflector (map 0
// sees what the viewer sees), with the same six directions.
#pragma once

#include <vector>

#include "core/camera.h"
#include "scene/scene.h"

namespace mirage {

struct DepthMapOptions {
  int size = 256;             // w: texels per side
  float fov_degrees = 20.0f;  // the depth-map camera's field of view
  int maps = 1;               // depth maps per object (1..6)
  int self_maps = 0;          // depth maps per non-planar reflector of itself (0..6)
};

struct DepthMapSpec {
  int instance = -1;         // the object (a group's first member: its space holds the camera)
  std::vector<int> members;  // a group's other members (still objects), captured with it
  int index = 0;             // among its object's maps
  bool reflector = false;    // a reflector's map of itself: normals, not colours
  // The camera in the object's space: it frames the mesh's bounding sphere (centre, radius)
  // from `from` (unit, from the centre towards the camera), with `up`.
  vec3 centre{0.0f}, from{0.0f, 0.0f, 1.0f}, up{0.0f, 1.0f, 0.0f};
  float radius = 1.0f;
};

// The non-planar diffuse instances of the object layer (scene/layers.h): the objects depth maps
// stand for.
std::vector<int> depthMappedObjects(const Scene& scene);

// The groups of depth-mapped objects (impostor_groups.h: each list's first member stands for
// it; empty: one group an object), each with options.maps specs framing the group's bounds,
// then the non-planar reflectors with options.self_maps (a group's specs are consecutive).
std::vector<DepthMapSpec> placeDepthMaps(const Scene& scene, const DepthMapOptions& options,
                                         const std::vector<std::vector<int>>& groups = {});

// The diffuse instances that have depth maps (and so no billboards), once each, members too.
std::vector<int> depthMappedInstances(const std::vector<DepthMapSpec>& specs);

// The sphere `spec`'s camera frames, with its object placed by `model`: xyz its world centre, w
// its radius (everything the map holds lies inside).
vec4 depthMapSphere(const DepthMapSpec& spec, const mat4& model);

// The camera of `spec` with its object placed by `model`: near and far planes enclose the
// bounding sphere.
View depthMapView(const DepthMapSpec& spec, const mat4& model, const DepthMapOptions& options);

}  // namespace mirage
