// Method `planar` with --planar-curved probes: a reflector that is not planar, seen in a mirrored
// view with a bounce left, shows a probe captured at its centre, looked up by direction (as
// `envmap` does) instead of its base colour.
#include "render/shaders/reflector.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_probes;
uniform int u_layer;  // the drawn reflector's cube: its place among the curved reflectors

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  return probe_radiance(u_probes, direction, float(u_layer), g_dRdx, g_dRdy);
}
