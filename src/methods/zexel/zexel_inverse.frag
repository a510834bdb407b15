// Method `zexel`, curved reflectors: the reflected ray is inverse-warped through the reflector's
// depth-preserving cube map (zexel_inverse_shared.h: the first point of its epipolar line where it
// passes behind the stored surface, discontinuities skipped) and shows the map's colour there,
// filtered over the ray differential's footprint as seen from the map's centre (a ray that
// strikes what the map did not see shows the surface beyond the silhouette that hid it); a ray
// that passes behind nothing shows the environment along it. The search reads the distances,
// and the bounds that cross empty stretches, from the cubes' distance pyramid
// (zexel_distance_pyramid.h); its pixels and reads are counted. The early depth test keeps
// hidden pixels out of the counts.
layout(early_fragment_tests) in;

#include "render/shaders/reflector.glsl"
#include "methods/zexel/zexel_shared.h"
#include "render/shaders/counter_slots.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_zexel_cubes;
layout(binding = MIRAGE_UNIT_ZEXEL_DISTANCES) uniform samplerCubeArray u_zexel_distances;
layout(std430, binding = MIRAGE_BIND_ZEXEL_COUNTERS) buffer CounterBlock {
  uint counters[MIRAGE_COUNTER_SLOTS * MIRAGE_COUNTER_SLOT_WORDS];
};
layout(std430, binding = MIRAGE_BIND_ZEXEL_FAR) readonly buffer FarBlock { float far_distance[]; };
uniform int u_layer;     // the drawn reflector's cube
uniform vec3 u_centre;   // and its centre
uniform float u_step_angle;
uniform int u_max_steps;
uniform float u_max_slope;
uniform float u_texel_angle;
uniform int u_top_level;  // the coarsest level of bounds read (0: none)

float zexel_cube_distance(int layer, vec3 direction, int level) {
  return textureLod(u_zexel_distances, vec4(direction, float(layer)), float(level)).r;
}
#include "methods/zexel/zexel_inverse_shared.h"

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  // A helper invocation (a quad's pixel off the triangle, run for derivatives) has no pixel to
  // shade and nothing after this needs its value: no search, which from its extrapolated
  // position could run the longest of all (the derivatives above were taken before).
  if (gl_HelperInvocation) return vec4(0.0f, 0.0f, 0.0f, MISS_DISTANCE);
  vec3 hit_direction;
  int status, samples;
  float t = zexel_inverse_warp(u_layer, position - u_centre, direction, u_step_angle,
                               u_max_steps, u_max_slope, u_texel_angle, u_top_level,
                               far_distance[u_layer], hit_direction, status, samples);
  int slot = counter_slot();
  atomicAdd(counters[slot + MIRAGE_ZEXEL_COUNT_CURVED_RAYS], 1u);
  atomicAdd(counters[slot + MIRAGE_ZEXEL_COUNT_CURVED_READS], uint(samples));
  if (t < 0.0f) return vec4(environment_radiance(direction), MISS_DISTANCE);
  // The ray's footprint at the hit (origin's and direction's differentials), as an angle seen
  // from the centre.
  float seen = max(length(position + t * normalize(direction) - u_centre), 1.0e-6f);
  vec3 dx = (g_dPdx + t * g_dRdx) / seen, dy = (g_dPdy + t * g_dRdy) / seen;
  return vec4(probe_radiance(u_zexel_cubes, hit_direction, float(u_layer), dx, dy).rgb, t);
}
