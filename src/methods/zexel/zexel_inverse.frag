// Method `zexel`, curved reflectors: the reflected ray is inverse-warped through the reflector's
// depth-preserving cube map (zexel_inverse_shared.h: the first point of its epipolar line where it
// passes behind the stored surface, discontinuities skipped) and shows the map's colour there,
// filtered over the ray differential's footprint as seen from the map's centre (a ray that
// strikes what the map did not see shows the surface beyond the silhouette that hid it); a ray
// that passes behind nothing shows the environment along it.
#include "render/shaders/reflector.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_zexel_cubes;
uniform int u_layer;     // the drawn reflector's cube
uniform vec3 u_centre;   // and its centre
uniform float u_step_angle;
uniform int u_max_steps;
uniform float u_max_slope;

float zexel_cube_distance(int layer, vec3 direction) {
  return textureLod(u_zexel_cubes, vec4(direction, float(layer)), 0.0f).a;
}
#include "methods/zexel/zexel_inverse_shared.h"

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  vec3 hit_direction;
  int status, samples;
  float t = zexel_inverse_warp(u_layer, position - u_centre, direction, u_step_angle,
                               u_max_steps, u_max_slope, hit_direction, status, samples);
  if (t < 0.0f) return vec4(environment_radiance(direction), MISS_DISTANCE);
  // The ray's footprint at the hit (origin's and direction's differentials), as an angle seen
  // from the centre.
  float seen = max(length(position + t * normalize(direction) - u_centre), 1.0e-6f);
  vec3 dx = (g_dPdx + t * g_dRdx) / seen, dy = (g_dPdy + t * g_dRdy) / seen;
  return vec4(probe_radiance(u_zexel_cubes, hit_direction, float(u_layer), dx, dy).rgb, t);
}
