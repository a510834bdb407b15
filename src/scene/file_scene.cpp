#include "scene/file_scene.h"

#include <filesystem>
#include <set>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "scene/loader_support.h"
#include "scene/mesh_stage.h"

namespace mirage {

namespace {

// The colour of parts the file gives no material: a light grey that shows the light and the sky.
constexpr vec3 kDefaultAlbedo{0.8f};

}  // namespace

Scene makeFileScene(const std::string& path, LoadedModel model) {
  Scene s;
  s.name = loader::fileStem(path);
  s.source = path;
  s.description = fmt::format("{} as it is", std::filesystem::path(path).filename().string());
  for (TextureImage& t : model.textures) s.textures.push_back(std::move(t));
  for (Material& m : model.materials) s.materials.push_back(std::move(m));

  int plain = -1;  // the material of parts without one, added when needed
  std::set<std::string> names;
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    Mesh& mesh = model.meshes[i];
    // Meshes are placed in world space once, as the default stage places them: an instance's
    // Transform (translation, rotation, scale) cannot hold every node matrix (shear).
    mesh.transform(model.mesh_transform[i]);
    loader::repairNormals(mesh);
    int material = model.mesh_material[i];
    if (material < 0) {
      if (plain < 0) plain = addMaterial(s, Material::diffuse("default", kDefaultAlbedo));
      material = plain;
    }
    const std::string& node = model.mesh_node[i];
    std::string name = !node.empty() ? node : !mesh.name.empty() ? mesh.name : s.name;
    if (mesh.name.empty()) mesh.name = fmt::format("{}-{}", s.name, i);
    addInstance(s, loader::uniqueName(name, names), addMesh(s, std::move(mesh)), material, {});
  }

  s.cameras = std::move(model.cameras);
  if (model.light) s.light = *model.light;
  if (s.cameras.empty()) {
    s.ensureCamera();
    spdlog::info("{}: the file has no camera; camera '{}' frames it", path, s.cameras[0].name);
  }
  if (s.reflectorInstances().empty())
    spdlog::warn(
        "{}: no part of the file has a mirror material (glTF: metallicFactor 1 and "
        "roughnessFactor 0), so nothing reflects: every method shows the same frame",
        path);
  s.validate();
  return s;
}

Scene loadModelScene(const std::string& path, StageMode mode) {
  LoadedModel model = loadSceneModel(path);
  const bool whole =
      mode == StageMode::kOff || (mode == StageMode::kAuto && !model.cameras.empty());
  if (!whole) return makeMeshStage(path, std::move(model));
  return makeFileScene(path, std::move(model));
}

}  // namespace mirage
