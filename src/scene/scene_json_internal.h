// What the parts of the scene-file parser share: the parse context and the helpers between
// scene_json.cpp (top level, environment, light, textures, materials, cameras) and
// scene_json_meshes.cpp (meshes, instances, animation, models).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_json_field.h"

namespace mirage::scene_json {

// `fit` of a mesh entry: uniform scale to `size` (largest extent), centred in x and z, and in y
// unless `ground` puts the lowest point on y = 0.
struct Fit {
  float size = 1.0f;
  bool ground = false;
};

struct MeshEntry {
  std::string name;
  std::string where;       // "file: meshes[i]", for messages
  std::string file_where;  // "file: meshes[i].file"
  std::string file;        // resolved path; empty for a procedural mesh
  std::optional<Fit> fit;
  int subdivide = 0;  // rounds of midpoint subdivision after loading and fitting (0..4)
  std::optional<Mesh> procedural;
  int scene_mesh = -1;  // index in Scene::meshes once used as one mesh
  bool model_loaded = false;
  // Once used as a model: per part, (index in Scene::meshes, index in Scene::materials or -1).
  std::vector<std::pair<int, int>> model_parts;
};

struct Context {
  std::string file;      // the scene file, for messages
  std::string base_dir;  // relative paths; empty: only assets: paths are allowed
  Scene scene;
  std::vector<MeshEntry> meshes;
  std::map<std::string, int> mesh_index;  // name -> index in `meshes`
  std::map<std::string, int> material_index;
  std::map<std::string, int> texture_index;
  int default_model_material = -1;  // for model parts without a material, added on first use
};

// The path a string field names, resolved (assets:, relative or absolute) and checked to exist.
std::string resolvePath(const Context& ctx, const Field& field);
// The index of the entry named by a string field in `names`; the error lists the names.
int lookupName(const std::map<std::string, int>& names, const Field& field, const char* kind);
// Rotation from Euler angles in degrees, applied about X, then Y, then Z.
quat eulerDegrees(const vec3& degrees);
mat4 fitMatrix(const Bounds3& bounds, const Fit& fit);

void parseMeshes(Context& ctx, const Field& root);
// A key's "time" (seconds in [0, 1e6]) after `previous`, the time of the key before it (none for
// the first): keys of animations, light keys and camera paths go in strictly increasing time.
float keyTime(const Field& key, std::optional<float> previous);
// One camera object; `index` names it when it has no name ("camera-<index + 1>").
CameraDesc parseCamera(const Field& f, size_t index);
void parseInstances(Context& ctx, const Field& root);
// "reflections": [{"reflectors", "method", "params"}, ...] (scene_json_reflections.cpp).
std::vector<ReflectionRule> parseReflections(const Field& list);
// "probes": [{"name", "position", "influence", "blend_distance", "proxy", "priority"}, ...]
// (scene_json_probes.cpp).
std::vector<ReflectionProbe> parseProbes(const Field& list);

}  // namespace mirage::scene_json
