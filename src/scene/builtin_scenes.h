// Procedural scenes that need no download: what the tests, the examples and the first benchmark
// figures use. `mirage scenes` lists them.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

struct SceneOptions {
  int reflectors = -1;  // spheres9: keep the first N reflectors (1..9); -1: all
};

struct BuiltinSceneInfo {
  std::string name;
  std::string description;
};

const std::vector<BuiltinSceneInfo>& builtinScenes();
bool isBuiltinScene(const std::string& name);
Scene makeBuiltinScene(const std::string& name, const SceneOptions& options = {});

// Helpers for building scenes in code.
int addMesh(Scene& scene, Mesh mesh);
int addMaterial(Scene& scene, Material material);
int addInstance(Scene& scene, std::string name, int mesh, int material, const Transform& transform);
Transform placeAt(vec3 translation, vec3 scale = vec3(1.0f), quat rotation = quat(1, 0, 0, 0));

}  // namespace mirage
