// Methods `envmap` (per-reflector probes) and `envmap-infinite` (distant environment only):
// the reflected ray is looked up by direction alone, as if the reflected scene were infinitely
// far away. The probe's alpha holds the distance from its centre, used for attenuation.
#include "render/shaders/reflector.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_probes;

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
#ifdef ENVMAP_INFINITE
  return vec4(environment_radiance(direction), MISS_DISTANCE);
#else
  vec4 coords = vec4(direction, float(reflector - 1));
  vec4 level0 = textureLod(u_probes, coords, 0.0f);
  vec3 color = frame.options.y != 0 ? textureGrad(u_probes, coords, g_dRdx, g_dRdy).rgb : level0.rgb;
  return vec4(color, level0.a);
#endif
}
