#include "scene/scene_loader.h"

#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "core/embedded_files.h"
#include "core/error.h"
#include "scene/file_scene.h"
#include "scene/model_loader.h"
#include "scene/scene_json.h"
#include "scene/scene_json_field.h"

namespace mirage {

namespace {

namespace fs = std::filesystem;

// Asset scenes are the JSON files under src/scene/scenes/, embedded in the binary.
constexpr std::string_view kSceneFolder = "scene/scenes/";
constexpr std::string_view kSceneExtension = ".json";

struct AssetScene {
  std::string name;  // the file's stem
  std::string file;  // its path under src/, for messages
  const char* text;
};

std::vector<AssetScene> assetScenes() {
  std::vector<AssetScene> out;
  for (const embedded::EmbeddedFile& f : embedded::files()) {
    std::string_view path = f.path;
    if (!path.starts_with(kSceneFolder) || !path.ends_with(kSceneExtension)) continue;
    std::string_view stem = path.substr(kSceneFolder.size());
    stem.remove_suffix(kSceneExtension.size());
    out.push_back({std::string(stem), std::string(path), f.content});
  }
  return out;
}

SceneListing describe(const AssetScene& scene) {
  SceneListing l;
  l.name = scene.name;
  scene_json::Json doc = scene_json::parseDocument(scene.file, scene.text);
  if (auto it = doc.find("description"); it != doc.end() && it->is_string())
    l.description = it->get<std::string>();
  for (const std::string& ref : sceneAssetReferences(scene.file, scene.text)) {
    std::string path = assetPath(scene.file, ref);
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) continue;
    l.available = false;
    l.missing = fmt::format("needs {} ({} does not exist); run scripts/fetch-assets", ref, path);
    break;
  }
  return l;
}

std::string sceneNames() {
  std::string names;
  for (const SceneListing& s : listScenes()) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

}  // namespace

std::string assetDirectory() {
  if (const char* dir = std::getenv("MIRAGE_ASSET_DIR"); dir && *dir) return dir;
  return MIRAGE_DEFAULT_ASSET_DIR;
}

std::vector<SceneListing> listScenes() {
  std::vector<SceneListing> out;
  for (const BuiltinSceneInfo& b : builtinScenes())
    out.push_back({b.name, b.description, true, {}});
  for (const AssetScene& a : assetScenes()) out.push_back(describe(a));
  return out;
}

Scene loadScene(const std::string& spec, const SceneOptions& options) {
  auto notModelFile = [&] {
    if (options.stage)
      throwInput(
          "--stage {} applies to model files only (.gltf, .glb, .obj, .ply, ...), not to '{}'",
          choiceName<StageMode>(kStageModes, *options.stage), spec);
  };
  if (isBuiltinScene(spec)) {
    notModelFile();
    return makeBuiltinScene(spec, options);
  }
  auto notSpheres9 = [&] {
    if (options.reflectors >= 0)
      throwInput("--reflectors applies to spheres9 and plaza only, not to '{}'", spec);
    if (options.objects >= 0) throwInput("--objects applies to plaza only, not to '{}'", spec);
  };
  for (const AssetScene& a : assetScenes()) {
    if (a.name != spec) continue;
    notSpheres9();
    notModelFile();
    SceneListing l = describe(a);
    if (!l.available) throwInput("--scene {}: not available: {}", spec, l.missing);
    // Embedded scenes have no folder: they refer to files only as assets:<path>.
    return parseSceneJson(a.file, a.text, "");
  }
  if (spec.ends_with(".json")) {
    notSpheres9();
    notModelFile();
    return loadSceneJson(spec);
  }
  if (isModelFile(spec)) {
    notSpheres9();
    return loadModelScene(spec, options.stage.value_or(StageMode::kAuto));
  }
  throwInput(
      "--scene {}: no such scene (built-in and asset scenes: {}; or a .json scene file or "
      "a mesh file)",
      spec, sceneNames());
}

}  // namespace mirage
