// Materials of the shared shading model (docs/architecture.md, "One shading model"): diffuse
// (albedo, checker or texture) and reflector (base colour, tint, reflectivity, Fresnel f0,
// distance attenuation, normal map).
#pragma once

#include <string>

#include "core/math.h"
#include "shading/gpu_types.h"

namespace mirage {

struct Material {
  enum class Kind { kDiffuse, kReflector };

  std::string name;
  Kind kind = Kind::kDiffuse;
  vec3 albedo{0.8f};        // diffuse albedo, or a reflector's base colour
  int albedo_texture = -1;  // index into Scene::textures (diffuse only), multiplies albedo
  float checker_scale =
      0;  // > 0: procedural checker, cells per uv unit, colours albedo/checker_color
  vec3 checker_color{0.1f};
  // Reflector parameters.
  vec3 tint{1.0f};
  float reflectivity = 1.0f;       // [0, 1]
  float fresnel_f0 = 1.0f;         // [0, 1]; 1 = a perfect mirror at every angle
  float attenuation_range = 0.0f;  // >= 0; 0 = no distance attenuation
  int normal_map = -1;             // index into Scene::textures
  bool planar = false;  // declared a planar mirror: the planar-mirror methods check and report it

  bool isReflector() const { return kind == Kind::kReflector; }
  shading::MaterialData gpuData() const;

  static Material diffuse(std::string name, vec3 albedo);
  static Material checker(std::string name, vec3 a, vec3 b, float cells_per_unit);
  static Material mirror(std::string name, vec3 base = vec3(0.05f), vec3 tint = vec3(1.0f));
};

}  // namespace mirage
