// The one shading model of mirage (docs/architecture.md, "One shading model"), shared verbatim
// by the GLSL shaders and the C++ ray tracer:
//  - diffuse surfaces: view-independent, albedo * (ambient + light * max(n.l, 0)), no shadows;
//    the same on an object, in any impostor captured of it, and in the ray tracer;
//  - reflectors: mix(base, tint * L_reflected, w), w = reflectivity * fresnel * attenuation(d);
//  - a reflector reached after the last allowed bounce shows its base colour (order 0 == `none`).
#ifndef MIRAGE_SHADING_SHADING_H
#define MIRAGE_SHADING_SHADING_H

#include "shading/glsl_compat.h"
#include "shading/gpu_types.h"

SHARED_BEGIN

// Hit distance used for rays that leave the scene (environment lookups).
SHARED_CONST float MISS_DISTANCE = 1.0e30f;
// A reflection probe's distance (half float, render/probe_array.h) at least this large is the
// sky. A half float holds at most 65504, and a driver may store MISS_DISTANCE as that or as
// +inf (llvmpipe clamps it), so the sky is told by a bound both readings pass; what a probe
// shows lies within its capture's far plane, 100 times the scene's radius, far nearer.
SHARED_CONST float PROBE_SKY_DISTANCE = 3.0e4f;

SHARED_FN vec3 shade_diffuse(vec3 albedo, vec3 normal, vec3 light_dir, vec3 light_color,
                             vec3 ambient) {
  return albedo * (ambient + light_color * max(dot(normal, light_dir), 0.0f));
}

// Procedural checkerboard albedo: `scale` cells per unit of texture coordinate.
SHARED_FN vec3 checker_albedo(vec2 uv, float scale, vec3 color_a, vec3 color_b) {
  vec2 cell = floor(uv * scale);
  float parity = mod(cell.x + cell.y, 2.0f);
  return parity < 0.5f ? color_a : color_b;
}

// The albedo of a diffuse material at texture coordinate uv, before any image texture.
SHARED_FN vec3 material_albedo(MaterialData m, vec2 uv) {
  if (m.checker.w > 0.0f) return checker_albedo(uv, m.checker.w, vec3(m.albedo), vec3(m.checker));
  return vec3(m.albedo);
}

SHARED_FN float fresnel_schlick(float f0, float cos_theta) {
  float m = clamp(1.0f - cos_theta, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (1.0f - f0) * m2 * m2 * m;
}

// 1 at distance 0, 1/2 at `range`, falling as 1/d^2 beyond; range <= 0 turns it off.
// Rays that miss (distance MISS_DISTANCE) are fully attenuated when attenuation is on.
SHARED_FN float distance_attenuation(float distance, float range) {
  if (range <= 0.0f) return 1.0f;
  if (distance >= MISS_DISTANCE) return 0.0f;
  return range * range / (range * range + distance * distance);
}

// The weight of the reflection in a reflector's colour.
SHARED_FN float reflection_weight(MaterialData m, float cos_theta, float distance) {
  float reflectivity = m.tint.w;
  return reflectivity * fresnel_schlick(m.params.x, cos_theta) *
         distance_attenuation(distance, m.params.y);
}

// A reflector's colour given the radiance arriving along the reflected ray and its hit distance.
// cos_theta is the cosine between the shading normal and the direction towards the viewer.
SHARED_FN vec3 shade_reflector(MaterialData m, float cos_theta, float distance, vec3 reflected) {
  float w = reflection_weight(m, cos_theta, distance);
  return mix(vec3(m.albedo), vec3(m.tint) * reflected, w);
}

// The colour of a reflector when no reflection is computed (method `none`, last bounce).
SHARED_FN vec3 reflector_base(MaterialData m) {
  return vec3(m.albedo);
}

// Mirror reflection of incident direction `incident` (pointing at the surface) about `normal`.
SHARED_FN vec3 reflect_direction(vec3 incident, vec3 normal) {
  return incident - 2.0f * dot(normal, incident) * normal;
}

// The shading normal of a reflector seen from the viewer's side: a surface seen from behind
// (a thin mirror, the inside of a shell) reflects on that side. The geometric normal only decides
// the side, so its orientation (winding, mirrored transforms) does not matter.
SHARED_FN vec3 facing_normal(vec3 shading_normal, vec3 geometric_normal, vec3 to_viewer) {
  vec3 ng = dot(geometric_normal, shading_normal) < 0.0f ? -geometric_normal : geometric_normal;
  return dot(ng, to_viewer) < 0.0f ? -shading_normal : shading_normal;
}

// Tangent-space normal map: t is the tangent (w = handedness), n the unit normal, texel the
// normal-map value in [0, 1]^3.
SHARED_FN vec3 perturb_normal(vec3 n, vec4 t, vec3 texel) {
  vec3 tangent = normalize(vec3(t) - n * dot(n, vec3(t)));
  vec3 bitangent = cross(n, tangent) * t.w;
  vec3 m = texel * 2.0f - vec3(1.0f);
  return normalize(m.x * tangent + m.y * bitangent + m.z * n);
}

SHARED_END

#endif  // MIRAGE_SHADING_SHADING_H
