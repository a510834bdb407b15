// Methods `envmap` (per-reflector probes), `envmap-box` (the same probes looked up through a box
// proxy of the room: a parallax-corrected cube map; PROBE_BOX) and `envmap-infinite` (distant
// environment only). `envmap` looks the reflected ray up by direction alone, as if the reflected
// scene were infinitely far away (render/shaders/probe_lookup.glsl).
#include "render/shaders/reflector.glsl"
#ifndef ENVMAP_INFINITE
#include "render/shaders/probe_lookup.glsl"
#endif

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
#ifdef ENVMAP_INFINITE
  return vec4(environment_radiance(direction), MISS_DISTANCE);
#else
  return probe_lookup(position, direction, reflector, g_dRdx, g_dRdy);
#endif
}
