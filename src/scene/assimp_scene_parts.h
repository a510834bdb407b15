// The cameras and the light of a file read through assimp (aiScene::mCameras, mLights), gathered
// node by node as AssimpConverter walks the node tree: each sits on the node of its name, and its
// position, view direction (mLookAt), up and light direction are in that node's space.
//
// Field of view: assimp's header calls mHorizontalFOV half the horizontal angle, but its
// importers store the whole angle (COLLADA's xfov, or 2 atan(aspect tan(yfov / 2)) from yfov), so
// it is read as the whole one: fov_y = 2 atan(tan(hfov / 2) / mAspect), or hfov itself with a
// warning when the file gives no aspect (mAspect 0). glTF through assimp (files needing Draco):
// assimp 5.2's glTF importer copies the node's translation into mPosition (a glTF camera sits at
// its node's origin, so it is dropped) and stores yfov x aspect as mHorizontalFOV (divided back).
// Orthographic cameras are skipped, point, spot, ambient and area lights and further directional
// lights ignored, each with a warning. The light's colour is mColorDiffuse (glTF: color x
// intensity already).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <assimp/scene.h>

#include "scene/model_loader.h"

namespace mirage::assimp {

class SceneParts {
 public:
  // `gltf`: the file is glTF (assimp's glTF importer's conventions above).
  SceneParts(const std::string& path, const aiScene& scene, bool gltf);

  // The cameras and lights named after `node`, placed by its world matrix.
  void addNode(const aiNode& node, const mat4& world);
  // Moves the cameras (uniquely named) and the light into `out`; warns about cameras and lights
  // no node placed.
  void finish(LoadedModel& out);

 private:
  void addCamera(unsigned index, const mat4& world);
  void addLight(unsigned index, const mat4& world);
  // The vertical field of view in degrees from the camera's horizontal one and aspect.
  float verticalFov(const std::string& what, const aiCamera& camera) const;

  const std::string& path_;
  const aiScene& scene_;
  bool gltf_;
  std::multimap<std::string, unsigned> cameras_by_node_, lights_by_node_;
  std::vector<char> camera_placed_, light_placed_;
  std::vector<CameraDesc> cameras_;
  std::optional<Light> light_;
  std::string light_name_;
};

}  // namespace mirage::assimp
