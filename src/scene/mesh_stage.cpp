#include "scene/mesh_stage.h"

#include <filesystem>

#include "scene/builtin_scenes.h"
#include "scene/loader_support.h"
#include "scene/model_loader.h"
#include "scene/procedural.h"
#include "scene/scene_json_internal.h"

namespace mirage {

namespace {

namespace fs = std::filesystem;

// "bunny" for bunny.ply and bunny.ply.gz alike.
std::string stemOf(const std::string& path) {
  fs::path p(path);
  if (p.extension() == ".gz") p = p.stem();
  return p.stem().string();
}

// A file's camera moved with the model by the stage's fit (a uniform scale and a translation).
CameraDesc fitted(CameraDesc c, const mat4& fit) {
  const float scale = fit[0][0];
  c.position = transformPoint(fit, c.position);
  c.target = transformPoint(fit, c.target);
  c.near_plane *= scale;
  c.far_plane *= scale;
  return c;
}

}  // namespace

LoadedModel loadSceneModel(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throwInput("--scene {}: no such file{}", path, fs::exists(path, ec) ? " (it is a folder)" : "");
  LoadedModel model = loadModel(path);
  if (model.meshes.empty()) throwInput("{}: the file holds no meshes", path);
  return model;
}

Scene makeMeshStage(const std::string& path) {
  return makeMeshStage(path, loadSceneModel(path));
}

Scene makeMeshStage(const std::string& path, LoadedModel model) {
  Scene s;
  s.name = stemOf(path);
  s.source = path;
  s.description = fmt::format("{} on the default stage", fs::path(path).filename().string());

  // The model first, fitted to the stage and standing on the ground at the origin.
  Bounds3 bounds;
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    if (i < model.mesh_transform.size()) model.meshes[i].transform(model.mesh_transform[i]);
    bounds.extend(model.meshes[i].bounds());
  }
  vec3 extent = bounds.extent();
  if (bounds.empty() || !(std::max({extent.x, extent.y, extent.z}) > 0.0f))
    throwInput("{}: the model has no extent (all its vertices coincide)", path);
  mat4 fit = scene_json::fitMatrix(bounds, {kStageModelSize, true});
  for (TextureImage& t : model.textures) s.textures.push_back(std::move(t));
  for (Material& m : model.materials) s.materials.push_back(std::move(m));
  int finish = -1;  // the mirror finish of parts without a material, added when needed
  bool any_reflector = false;
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    Mesh& mesh = model.meshes[i];
    mesh.transform(fit);
    if (mesh.name.empty()) mesh.name = fmt::format("{}-{}", s.name, i);
    int material = i < model.mesh_material.size() ? model.mesh_material[i] : -1;
    if (material < 0) {
      if (finish < 0) finish = addMaterial(s, Material::mirror("mirror-finish"));
      material = finish;
    }
    any_reflector = any_reflector || s.materials[size_t(material)].isReflector();
    std::string name = model.meshes.size() == 1 ? s.name : mesh.name;
    addInstance(s, name, addMesh(s, std::move(mesh)), material, {});
  }

  // The ground and things to reflect, outside the model's 2 x 2 footprint and out of the line
  // of sight from the camera (front-left).
  int floor = addMesh(s, procedural::quad(24.0f, 24.0f, 1.0f));
  int checker = addMaterial(s, Material::checker("checker", kCheckerLight, kCheckerDark, 1.0f));
  addInstance(s, "floor", floor, checker, {});
  addBox(s, "red-box", {2.5f, 0.35f, -1.5f}, vec3(0.35f), {0.85f, 0.18f, 0.12f}, 20.0f);
  addBox(s, "green-box", {-1.7f, 0.3f, -1.9f}, vec3(0.3f), {0.2f, 0.7f, 0.25f}, -15.0f);
  addBox(s, "blue-box", {0.2f, 0.45f, -2.6f}, {0.3f, 0.45f, 0.3f}, {0.15f, 0.3f, 0.85f}, 35.0f);
  addBox(s, "yellow-box", {1.5f, 0.25f, 2.1f}, vec3(0.25f), {0.9f, 0.8f, 0.15f}, 10.0f);
  if (!any_reflector) {
    // Nothing on stage would reflect the model: a mirror sphere beside it does.
    int sphere = addMesh(s, procedural::sphere(0.75f, 96, 48));
    int mirror = addMaterial(s, Material::mirror("mirror"));
    addInstance(s, "mirror-sphere", sphere, mirror, placeAt({2.0f, 0.75f, 0.5f}));
  }

  CameraDesc cam;
  cam.name = "main";
  cam.position = {-2.9f, 2.3f, 4.3f};
  cam.target = {0.35f, 0.7f, 0.0f};
  cam.fov_y_degrees = 45.0f;
  s.cameras.push_back(cam);
  for (const CameraDesc& c : model.cameras) s.cameras.push_back(fitted(c, fit));
  loader::uniqueCameraNames(path, s.cameras);
  s.validate();
  return s;
}

}  // namespace mirage
