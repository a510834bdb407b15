// What a reflector shader's reflected_radiance works with, whichever pass runs it (a pass over
// the reflectors' triangles, reflector.glsl; a screen-space pass over their G-buffer,
// reflector_screen.glsl): the reflected ray's differentials, the environment and probe lookups
// filtered by them.
#include "render/shaders/common.glsl"
#include "render/shaders/probe_radiance.glsl"

// Screen-space derivatives of the reflected direction, taken in uniform control flow so that
// methods can filter lookups (textureGrad) inside loops and branches.
vec3 g_dRdx = vec3(0.0f);
vec3 g_dRdy = vec3(0.0f);
// ... and of the shaded point: with the direction's, the reflected ray's differential.
vec3 g_dPdx = vec3(0.0f);
vec3 g_dPdy = vec3(0.0f);

// The scene's distant environment along `direction`, filtered by the reflected ray's footprint
// when mip-mapping is on.
vec3 environment_radiance(vec3 direction) {
  return environment_lookup(direction, g_dRdx, g_dRdy);
}

#ifndef MIRAGE_NO_REFLECTION
vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector);
#endif
