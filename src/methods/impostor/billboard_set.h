// Which billboards a scene needs and where they stand (the impostor paper, §3), computed on the
// CPU from the scene at a time; billboard_capture.h renders their textures.
//
//  - A planar diffuse object (floor, table top, wall) is its own billboard: a square in its
//    plane, shared by every reflector, captured head-on (exact: a pinhole camera facing a plane
//    images it without distortion).
//  - Any other diffuse object gets one billboard per reflector: the plane through the object's
//    centre B perpendicular to the line from B to the reflector's centre, captured by a narrow
//    camera (10 degrees by default) on that line, from the reflector's side, framing the
//    object's bounding sphere.
//  - Each reflector k gets one reflective billboard per other reflector i, placed like a
//    diffuse billboard of k for i: a ray leaving i tests the R - 1 billboards of the others,
//    never its own, and after bouncing off k it tests the billboards built for k.
#pragma once

#include <vector>

#include "core/bounds.h"
#include "core/camera.h"
#include "methods/impostor/billboard_shared.h"
#include "scene/layers.h"
#include "scene/scene.h"

namespace mirage {

struct BillboardSpec {
  enum class Kind { kPlanar, kObject, kReflective };
  Kind kind = Kind::kObject;
  int object = -1;           // the instance it stands for (a group's first member)
  std::vector<int> members;  // a group's other members, captured with `object` (still objects)
  int reflector = -1;        // the reflector (0-based) whose rays test it; -1 for planar (all)
  int represents = -1;       // reflective: the reflector (0-based) it stands for
  CameraDesc camera;         // captures its texture: square image, up = edge_v, right = edge_u
  vec3 corner{0.0f}, edge_u{0.0f}, edge_v{0.0f};
  // The motion its object made since its capture (BillboardCapture carries an old capture along
  // with it): the quad is carried by it, and a reflective billboard's stored surface points and
  // normals in the shader (BillboardCarry). The identity for a fresh capture.
  mat4 carry{1.0f};
  // Planar: it stands for one planar part of an environment instance (scene/layers.h), not for
  // the whole of `object`; its capture sees only a thin slab around the part's plane.
  bool part = false;
  int layer = -1;           // in the surface array: colour (diffuse) or normal (reflective)
  int position_layer = -1;  // reflective: in the surface-point array
};

struct BillboardSetOptions {
  float fov_degrees = 10.0f;  // the capture camera's field of view (objects, reflectors)
  bool objects = true;        // billboards for non-planar diffuse objects too (else planar only)
  float morph_height = 0.0f;  // > 0: transition walls of this height around the ground (§3.2)
  bool sides = true;          // a planar reflector's list per side of its plane (BillboardRange)
  // Lists per direction cell (billboard_shared.h, direction_cell): g x g cells a cube face; 0:
  // one list a reflector (and side).
  int cells = 0;
  int texels = 256;  // the billboards' texture side, in texels (their coverage's resolution)
  // Instances that another impostor stands for (depth maps): no billboard, and not in the
  // captured environment.
  std::vector<int> excluded;
  // Impostor groups (impostor_groups.h): the non-planar diffuse objects that share one
  // billboard per reflector, each list's first member standing for it. Empty: one an object.
  std::vector<std::vector<int>> groups;
  // The scene's layers (scene/layers.h; BillboardStage fills them in): an environment instance
  // that is not flat is a planar billboard per planar part, what its parts leave goes into the
  // captured environment. Empty: every diffuse instance is an object.
  SceneLayers layers;
};

struct BillboardSet {
  std::vector<BillboardSpec> billboards;
  // Per reflector (0-based) and direction cell, the entries its rays test, into `entries`: the
  // list of reflector r and cell c is ranges[billboard_list_index(r, dir, cells)].
  std::vector<shading::BillboardRange> ranges;
  int cells = 0;
  std::vector<int> entries;
  int surface_layers = 0, position_layers = 0;
  // Diffuse instances with no billboard (they go into the captured environment).
  std::vector<int> unbillboarded;
  // The billboard-to-environment morph (§3.2), when on: the ground's billboard (tested through
  // the box it forms with its transition walls, not through the lists), the box, and the
  // environment's centre E. The captured environment then shows the ground too.
  int ground = -1;  // index into `billboards`, -1: no morph
  Bounds3 morph_box;
  vec3 environment_centre{0.0f};

  // What the captured environment shows besides the distant environment (none: the method
  // uses the scene's environment as it is).
  std::vector<int> environmentInstances() const;

  std::vector<shading::BillboardData> gpuData(const Scene& scene) const;
  // Each billboard's carry (BillboardSpec::carry) as the shader reads it.
  std::vector<shading::BillboardCarry> carryData() const;
};

// The diffuse instances a billboard set stands for at `time` (reflectors and `excluded` left
// out): the planar ones (each its own billboard), the others that get billboards of their own or
// of their group's, and the others that go into the captured environment instead
// (--billboard-objects planar).
struct BillboardedInstances {
  std::vector<int> planar, objects, unbillboarded;
  std::vector<EnvironmentPlane> parts;  // the planar parts of environment instances not flat
};
BillboardedInstances billboardedInstances(const Scene& scene, const BillboardSetOptions& options,
                                          float time);

// The billboards of `scene` with its instances placed at `time`.
BillboardSet placeBillboards(const Scene& scene, float time, const BillboardSetOptions& options);

}  // namespace mirage
