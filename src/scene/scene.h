// A scene: meshes, materials, textures, instances (with transforms and keyframed animation),
// cameras, one directional light plus ambient, and the distant environment.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "core/camera.h"
#include "core/image.h"
#include "scene/animation.h"
#include "scene/deformation.h"
#include "scene/layers.h"
#include "scene/material.h"
#include "scene/mesh.h"
#include "scene/probes.h"

namespace mirage {

// A key of a moving light: where it shines from and its colour at `time`.
struct LightKey {
  float time = 0.0f;                 // seconds; strictly increasing
  vec3 direction{0.0f, 1.0f, 0.0f};  // unit, towards the light
  vec3 color{1.0f};
};

struct Light {
  vec3 direction = glm::normalize(vec3(0.45f, 1.0f, 0.35f));  // unit, towards the light
  vec3 color{0.95f, 0.93f, 0.88f};
  vec3 ambient{0.25f, 0.27f, 0.30f};
  // Keyframes (a moving light), empty for a fixed one: between keys the direction turns at a
  // constant angular speed (slerp; successive keys less than 180° apart) and the colour is
  // interpolated linearly; before the first key the first holds, after the last the last, or the
  // keys repeat with `loop`. The procedural sky's sun stays where the light is at time 0 (the
  // environment is captured once; docs/scene-format.md).
  std::vector<LightKey> keys;
  bool loop = false;

  float duration() const { return keys.empty() ? 0.0f : keys.back().time; }
  // This light at `time`: direction and colour from the keys, no keys of its own.
  Light at(float time) const;
};

struct EnvironmentDesc {
  std::string image;              // equirectangular HDR/EXR/PNG; empty: procedural sky
  float intensity = 1.0f;         // radiance scale
  float rotation_degrees = 0.0f;  // about +Y
  float clamp = 0.0f;             // > 0: clamp radiance (tames HDR suns); 0: off
  int cube_size = 0;              // cube-map face size; 0: automatic
};

struct TextureImage {
  std::string name;  // path or embedded name, for messages
  Image image;       // linear values (sRGB textures are decoded on load)
  bool srgb = true;
};

struct Instance {
  std::string name;
  int mesh = -1;
  int material = -1;
  Transform transform;  // used when there is no animation
  Animation animation;  // keyframed transforms, overriding `transform`
  // A procedural deformation of the mesh over time (reflectors only; the mesh is this
  // instance's own).
  Deformation deformation;
  // The layer its scene file gives it (scene/layers.h); none: the default rule decides.
  std::optional<Layer> layer;

  bool deforms() const { return deformation.active(); }

  mat4 matrixAt(float time) const {
    return animation.empty() ? transform.matrix() : animation.at(time).matrix();
  }
};

// One entry of a scene's reflection assignment (the top-level "reflections" of a scene file,
// or `--assign`): the reflectors it covers (instance or material names, or globs of them; "*"
// alone is the default entry, for every reflector no other entry names), the method that draws
// them and that method's parameters as text. Plain data: methods/assignment.h resolves and
// validates it against the scene and the method registry.
struct ReflectionRule {
  std::vector<std::string> reflectors;
  std::string method;
  std::map<std::string, std::string> params;  // name -> value ("order" sets the entry's K)
  std::string where;  // where it was given, for messages: "scene.json: reflections[1]", "--assign"
};

struct Scene {
  std::string name;
  std::string source;  // the file it came from, or "builtin"
  std::string description;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<TextureImage> textures;
  std::vector<Instance> instances;
  std::vector<CameraDesc> cameras;  // at least one after validation
  Light light;
  EnvironmentDesc environment;
  std::vector<ReflectionRule> reflections;  // empty: no assignment (method `mixed` needs one)
  std::vector<ReflectionProbe> probes;      // empty: one probe at each reflector, its own

  bool isReflector(int instance) const {
    return materials[size_t(instances[size_t(instance)].material)].isReflector();
  }
  // Instances with reflector materials, in scene order; reflector id = position + 1.
  std::vector<int> reflectorInstances() const;
  // The other instances (diffuse materials), in scene order.
  std::vector<int> diffuseInstances() const;
  size_t triangleCount() const;
  // The instance's mesh at `time` into `out`: deformed when the instance deforms, else a copy.
  void meshAt(int instance, float time, Mesh& out) const;
  Light lightAt(float time) const { return light.at(time); }
  // World bounds of all instances at `time` (a deforming instance's grown by its amplitude).
  Bounds3 bounds(float time = 0.0f) const;
  Bounds3 instanceBounds(int instance, float time = 0.0f) const;
  // An instance's bounds in object space, holding every shape its deformation takes.
  Bounds3 localBounds(int instance) const;
  // The camera with this name (empty: the first); throws InputError listing the names.
  const CameraDesc& camera(const std::string& name = "") const;
  // Animation length in seconds (0 for a static scene): the longest instance or light animation,
  // or a deformation's period.
  float duration() const;
  bool animated() const { return duration() > 0.0f; }

  // Checks references, ranges and meshes; throws InputError naming the scene and the field.
  void validate() const;
  // Adds a camera framing the scene if none is given.
  void ensureCamera();
};

// The instance's mesh is flat (its thinnest bounds extent below 1e-4 of its largest) and does
// not deform: then
// `normal` receives its world-space plane normal under `model`.
bool isPlanarInstance(const Scene& scene, int instance, const mat4& model, vec3* normal = nullptr);
// The reflector instances that are planar at time 0, in order; `not_planar` (when given)
// receives how many others there are. Reflectors whose material declares them planar but that
// are not are logged as a warning naming `method`, the instance and the material: the method
// shows them its other way.
std::vector<int> planarReflectors(const Scene& scene, int* not_planar = nullptr,
                                  const char* method = "");

// The plane of a planar instance under `model`: the centre of its mesh's bounds (on the plane)
// and the unit normal turned towards `eye`; false when the instance is not planar or `eye` lies
// in its plane (edge-on).
bool planarInstancePlane(const Scene& scene, int instance, const mat4& model, const vec3& eye,
                         vec3& point, vec3& normal);

// A texture's value at `uv`: bilinear, repeating, level 0 (what the GPU samples at level 0 with
// GL_REPEAT; the image's row 0 is at v = 1).
vec3 sampleTexture(const Image& image, vec2 uv);

}  // namespace mirage
