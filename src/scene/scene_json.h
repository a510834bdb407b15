// JSON scene files (docs/scene-format.md): meshes (files or procedural), materials, textures,
// instances with keyframed animation, cameras, light and environment. Every error is an
// InputError naming the file, the JSON path of the field and the allowed values.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

// Reads and parses a scene file; relative paths in it are relative to its folder.
Scene loadSceneJson(const std::string& path);

// Parses scene text. `file` names it in messages and becomes Scene::source; relative paths are
// resolved against `base_dir`, and are an error when `base_dir` is empty (embedded scenes may
// only use `assets:` paths).
Scene parseSceneJson(const std::string& file, const std::string& text, const std::string& base_dir);

// The `assets:` references of a scene text (e.g. "assets:teapot/teapot.ply"), in order of
// appearance, without loading anything: what decides whether an asset scene is available.
std::vector<std::string> sceneAssetReferences(const std::string& file, const std::string& text);

// Where an `assets:` reference lives on disk, under assetDirectory(); throws InputError naming
// `where` when the reference is not a relative path inside the asset directory.
std::string assetPath(const std::string& where, const std::string& reference);

// The prefix that marks a path relative to the asset directory.
inline constexpr const char* kAssetPrefix = "assets:";

}  // namespace mirage
