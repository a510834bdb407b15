// The reflected scene in layers (docs/architecture.md, "Layers"), decided once per scene and
// shared by every method. The seed techniques represent compact objects near a reflector and
// leave the rest — the sky, and the geometry that encloses the reflectors or is too large for an
// object representation — to an environment:
//  - `environment`: an instance whose bounds hold a reflector's, or whose bounds are more than
//    kEnvironmentSizeFactor times the size of the reflectors' neighbourhood (the bounds of every
//    reflector). Its planar parts are exact planar surfaces for the methods that have them (the
//    impostor paper's planar billboards); the rest of it is seen through probes.
//  - `object`: every other diffuse instance, in each method's own representation.
// A scene file may set an instance's layer ("layer": "environment" | "object"). Reflectors are
// the receivers, in no layer. An animated instance is an object unless its file says otherwise
// (its bounds move).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/choices.h"
#include "core/math.h"

namespace mirage {

struct Mesh;
struct Scene;

enum class Layer { kObject, kEnvironment };
inline constexpr Choice<Layer> kLayers[] = {{"object", Layer::kObject},
                                            {"environment", Layer::kEnvironment}};

// How many times the reflectors' neighbourhood an instance's bounds must be to be environment:
// a floor or a terrain under a few mirrors is, a table or a column beside them is not.
inline constexpr float kEnvironmentSizeFactor = 4.0f;

// A planar part of a mesh: its triangles that lie in one plane, in the mesh's own space.
struct PlanarPart {
  vec3 normal{0.0f};                             // unit, the side its triangles face
  vec3 corner{0.0f}, edge_u{0.0f}, edge_v{0.0f};  // the rectangle holding its triangles
  float area = 0.0f;                             // of its triangles
  int triangles = 0;
};

// A mesh's planar parts, largest first: each plane that holds at least kMinPartShare of the
// mesh's area (to 1e-4 of its size, normals within about 1 degree, facing alike), at most
// kMaxPlanarParts of them; `rest_area` (when given) receives the area of its other triangles.
inline constexpr int kMaxPlanarParts = 64;
inline constexpr float kMinPartShare = 0.01f;
std::vector<PlanarPart> planarParts(const Mesh& mesh, float* rest_area = nullptr);

struct InstanceLayer {
  bool reflector = false;  // then in no layer
  Layer layer = Layer::kObject;
  std::string why;  // what decided it, for `mirage scenes -v` and reports
};

// An environment instance's planar part, in its instance's object space.
struct EnvironmentPlane {
  int instance = -1;
  PlanarPart part;
};

struct SceneLayers {
  std::vector<InstanceLayer> instances;  // one per instance, in scene order
  // The environment instances' planar parts (a flat instance is one part).
  std::vector<EnvironmentPlane> planes;
  // The environment instances with triangles outside their planar parts (seen through probes).
  std::vector<int> rest;

  bool environment(int instance) const {
    const InstanceLayer& l = instances[size_t(instance)];
    return !l.reflector && l.layer == Layer::kEnvironment;
  }
  // The planar parts of `instance`.
  std::vector<PlanarPart> planesOf(int instance) const;
  // The environment instances (diffuse only), in scene order.
  std::vector<int> environmentInstances() const;
  // "environment", "object" or "reflector".
  const char* name(int instance) const;
};

// The layers of `scene` at time 0, by the rule above and the scene file's choices
// (Instance::layer).
SceneLayers sceneLayers(const Scene& scene);

}  // namespace mirage
