// Finding and loading scenes by what the user types after --scene: a built-in scene name, an
// asset scene name (available once scripts/fetch-assets has run), a JSON scene file, or a model
// file: shown as it is when it has a camera of its own (scene/file_scene.h), else put on the
// default stage (scene/mesh_stage.h); SceneOptions::stage decides otherwise.
#pragma once

#include <string>
#include <vector>

#include "scene/builtin_scenes.h"
#include "scene/scene.h"

namespace mirage {

struct SceneListing {
  std::string name;
  std::string description;
  bool available = true;
  std::string missing;  // why it is not available and how to get it
};

// Built-in scenes first, then the asset scenes.
std::vector<SceneListing> listScenes();

// Loads `spec`; throws InputError naming the scene or file and what is wrong with it.
Scene loadScene(const std::string& spec, const SceneOptions& options = {});

// Where scripts/fetch-assets put the data packages: $MIRAGE_ASSET_DIR, else the build's default.
std::string assetDirectory();

}  // namespace mirage
