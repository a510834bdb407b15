// The procedural sky used when a scene names no environment image: a horizon-to-zenith
// gradient, a darker ground below the horizon and a soft sun in the light's direction.
// Smooth everywhere except the sun, so a modest cube-map resolution represents it well.
#ifndef MIRAGE_SHADING_SKY_H
#define MIRAGE_SHADING_SKY_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

SHARED_FN vec3 procedural_sky(vec3 direction, vec3 sun_dir, vec3 sun_color) {
  vec3 d = normalize(direction);
  vec3 zenith = vec3(0.18f, 0.36f, 0.78f);
  vec3 horizon = vec3(0.78f, 0.84f, 0.92f);
  vec3 ground = vec3(0.26f, 0.23f, 0.20f);
  vec3 color;
  if (d.y >= 0.0f) {
    color = mix(horizon, zenith, sqrt(d.y));
  } else {
    color = mix(horizon * 0.55f, ground, sqrt(min(-d.y * 4.0f, 1.0f)));
  }
  float s = max(dot(d, normalize(sun_dir)), 0.0f);
  float s8 = s * s * s * s * s * s * s * s;
  float s64 = s8 * s8 * s8 * s8 * s8 * s8 * s8 * s8;
  color += sun_color * (0.25f * s8 * s8 + 2.0f * s64 * s64 * s64 * s64);
  return color;
}

SHARED_END

#endif  // MIRAGE_SHADING_SKY_H
