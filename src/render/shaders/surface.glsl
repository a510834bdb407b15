// Fragment-side inputs of a scene surface and the lookups of its material's textures.
#include "render/shaders/common.glsl"
#include "shading/octahedral.h"

in SurfaceData {
  vec3 world_position;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  flat int instance;
  flat ivec4 ids;  // material, reflector id, albedo texture, normal map (see scene.vert)
} v_in;

layout(binding = MIRAGE_UNIT_ALBEDO) uniform sampler2D u_albedo;
layout(binding = MIRAGE_UNIT_NORMAL_MAP) uniform sampler2D u_normal_map;

layout(location = 0) out vec4 out_color;  // rgb: linear radiance; a: distance from the eye
layout(location = 1) out uint out_id;     // reflector id, 0 for everything else

MaterialData surface_material() { return materials[v_in.ids.x]; }

vec3 surface_albedo(MaterialData m) {
  vec3 albedo = material_albedo(m, v_in.uv);
  if (v_in.ids.z >= 0) albedo *= texture(u_albedo, v_in.uv).rgb;
  return albedo;
}

// The interpolated normal, perturbed by the material's normal map if it has one.
vec3 surface_normal() {
  vec3 n = normalize(v_in.normal);
  if (v_in.ids.w >= 0) n = perturb_normal(n, v_in.tangent, texture(u_normal_map, v_in.uv).rgb);
  return n;
}

float eye_distance() { return length(v_in.world_position - frame.eye.xyz); }

#ifdef MIRAGE_GBUFFER
// A G-buffer pass (method `ssr`) also writes the surface's normal turned towards the viewer
// (xy: octahedral_encode), and for a reflector its material index + 1 (z) and its reflector id
// (w); both 0 on a diffuse surface.
layout(location = 2) out vec4 out_normal;
void write_gbuffer(bool reflector) {
  vec3 p = v_in.world_position;
  vec3 to_viewer = normalize(frame.eye.xyz - p);
  vec3 n = facing_normal(surface_normal(), cross(dFdx(p), dFdy(p)), to_viewer);
  vec2 ids = reflector ? vec2(float(v_in.ids.x + 1), float(v_in.ids.y)) : vec2(0.0f);
  out_normal = vec4(octahedral_encode(n), ids);
}
#else
void write_gbuffer(bool reflector) {}
#endif
