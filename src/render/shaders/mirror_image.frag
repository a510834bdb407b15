// A planar mirror that shows, at its own pixel, an image made for it from the mirrored eye (the
// scene re-rendered: method `planar`).
// That image's alpha is the distance from the mirrored eye to what it saw: the distance from the
// real eye through the mirror point, so the reflected ray's length is that minus the distance
// from the eye to the mirror point (the sky keeps MISS_DISTANCE).
#include "render/shaders/reflector.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform sampler2D u_mirrored;

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  vec4 seen = texelFetch(u_mirrored, ivec2(gl_FragCoord.xy), 0);
  float distance = seen.a >= MISS_DISTANCE ? MISS_DISTANCE
                                           : max(seen.a - length(frame.eye.xyz - position), 0.0f);
  return vec4(seen.rgb, distance);
}
