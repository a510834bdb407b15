// The cameras and the light of a glTF file, gathered node by node as GltfConverter walks the
// scene's node tree (docs/scene-format.md, "Whole scenes from files").
//
// Cameras: a node's perspective camera looks down its node's -Z with +Y up; position, view
// direction and up are the node's world matrix applied to (0,0,0,1), (0,0,-1,0) and (0,1,0,0),
// normalised (a node may scale). yfov, znear, zfar and aspectRatio are checked (InputError naming
// the file, the camera and the field); orthographic cameras are skipped with a warning (mirage's
// views are pinholes). A camera is named after the glTF camera, else its node, else camera<i>;
// repeated names get -2, -3, ... with a warning.
//
// Light: KHR_lights_punctual. The first directional light met becomes the scene's light: its
// direction (towards the light) is -normalize(world * (0,0,-1,0)), its colour color x intensity
// (as three.js's loader takes it). Point and spot lights, and further directional ones, are
// ignored with a warning: mirage has one directional light.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/gltf_model.h"
#include "scene/model_loader.h"

namespace mirage::gltf {

// The far plane of a camera without zfar (an infinite projection, which mirage's views do not
// have): this many scene units, or twice the distance to the farthest corner of the file's bounds
// when that is farther.
inline constexpr float kInfiniteFar = 1000.0f;

class SceneParts {
 public:
  SceneParts(const std::string& path, const tinygltf::Model& model) : path_(path), gltf_(model) {}

  // The camera and the light that node `index` carries, if any, placed by its world matrix.
  void addNode(int index, const tinygltf::Node& node, const mat4& world);
  // Moves the cameras (uniquely named, far planes made finite for the meshes already in `out`)
  // and the light into `out`.
  void finish(LoadedModel& out);

 private:
  void addCamera(int index, const tinygltf::Node& node, const mat4& world);
  void addLight(int index, const tinygltf::Node& node, const mat4& world);
  // The light's colour times its intensity, checked.
  vec3 lightColor(const std::string& what, const tinygltf::Light& light) const;

  const std::string& path_;
  const tinygltf::Model& gltf_;
  std::vector<CameraDesc> cameras_;
  std::vector<size_t> infinite_;  // cameras without zfar
  std::optional<Light> light_;
  std::string light_name_;  // the light's name in messages
};

}  // namespace mirage::gltf
