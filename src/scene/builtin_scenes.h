// Procedural scenes that need no download: what the tests, the examples and the first benchmark
// figures use. `mirage scenes` lists them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/choices.h"
#include "scene/scene.h"

namespace mirage {

// How a model file given as the scene is shown (--stage): kAuto, as it is when it has a camera
// and on the default stage otherwise; kOn, on the default stage (its cameras fitted along);
// kOff, as it is (framed by a camera of mirage's when it has none).
enum class StageMode { kAuto, kOn, kOff };
inline constexpr Choice<StageMode> kStageModes[] = {
    {"auto", StageMode::kAuto}, {"on", StageMode::kOn}, {"off", StageMode::kOff}};

struct SceneOptions {
  int reflectors = -1;  // spheres9 (1..9), plaza (1..32): keep the first N reflectors; -1: all
  int objects = -1;     // plaza: N diffuse objects (10..1000); -1: the scene's own
  // Model files only (--stage); nothing: not given, which is kAuto.
  std::optional<StageMode> stage;
};

struct BuiltinSceneInfo {
  std::string name;
  std::string description;
};

const std::vector<BuiltinSceneInfo>& builtinScenes();
bool isBuiltinScene(const std::string& name);
Scene makeBuiltinScene(const std::string& name, const SceneOptions& options = {});

// The checkerboard colours of the built-in scenes and the default stage.
inline const vec3 kCheckerLight{0.85f, 0.85f, 0.82f};
inline const vec3 kCheckerDark{0.10f, 0.10f, 0.12f};

// Helpers for building scenes in code.
int addMesh(Scene& scene, Mesh mesh);
int addMaterial(Scene& scene, Material material);
int addInstance(Scene& scene, std::string name, int mesh, int material, const Transform& transform);
// One mesh with its own material, placed once: addMesh, addMaterial and addInstance in turn.
int addObject(Scene& scene, std::string name, Mesh mesh, Material material,
              const Transform& transform);
// A diffuse box of half extents `half` centred at `center`, turned by `yaw` degrees about +Y.
void addBox(Scene& scene, const char* name, vec3 center, vec3 half, vec3 color, float yaw = 0.0f);
Transform placeAt(vec3 translation, vec3 scale = vec3(1.0f), quat rotation = quat(1, 0, 0, 0));

}  // namespace mirage
