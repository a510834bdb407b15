#include "scene/material.h"

namespace mirage {

shading::MaterialData Material::gpuData() const {
  shading::MaterialData d{};
  d.albedo = vec4(albedo, 1.0f);
  d.tint = vec4(tint, reflectivity);
  d.params = vec4(fresnel_f0, attenuation_range, 0.0f, 0.0f);
  d.checker = vec4(checker_color, checker_scale);
  d.kind = ivec4(isReflector() ? MIRAGE_MATERIAL_REFLECTOR : MIRAGE_MATERIAL_DIFFUSE,
                 albedo_texture, normal_map, 0);
  return d;
}

Material Material::diffuse(std::string name, vec3 albedo) {
  Material m;
  m.name = std::move(name);
  m.albedo = albedo;
  return m;
}

Material Material::checker(std::string name, vec3 a, vec3 b, float cells_per_unit) {
  Material m = diffuse(std::move(name), a);
  m.checker_color = b;
  m.checker_scale = cells_per_unit;
  return m;
}

Material Material::mirror(std::string name, vec3 base, vec3 tint) {
  Material m;
  m.name = std::move(name);
  m.kind = Kind::kReflector;
  m.albedo = base;
  m.tint = tint;
  return m;
}

}  // namespace mirage
