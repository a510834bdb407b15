#include "scene/scene_loader.h"

#include <cstdlib>

#include "core/error.h"

namespace mirage {

std::string assetDirectory() {
  if (const char* dir = std::getenv("MIRAGE_ASSET_DIR"); dir && *dir) return dir;
  return MIRAGE_DEFAULT_ASSET_DIR;
}

std::vector<SceneListing> listScenes() {
  std::vector<SceneListing> out;
  for (const BuiltinSceneInfo& b : builtinScenes()) out.push_back({b.name, b.description, true, {}});
  return out;
}

Scene loadScene(const std::string& spec, const SceneOptions& options) {
  if (isBuiltinScene(spec)) return makeBuiltinScene(spec, options);
  std::string names;
  for (const SceneListing& s : listScenes()) names += (names.empty() ? "" : ", ") + s.name;
  throwInput("--scene {}: no such scene (built-in: {}; or a .json scene file or a mesh file)", spec,
             names);
}

}  // namespace mirage
