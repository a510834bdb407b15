// Output transform: exposure, tone map, sRGB encoding. Applied to the linear image of every
// method and of the ray tracer alike; metrics compare the results of this transform.
#ifndef MIRAGE_SHADING_TONEMAP_H
#define MIRAGE_SHADING_TONEMAP_H

#include "shading/glsl_compat.h"
#include "shading/gpu_types.h"

SHARED_BEGIN

SHARED_FN float tonemap_channel(float x, int op) {
  x = max(x, 0.0f);
  if (op == MIRAGE_TONEMAP_REINHARD) return x / (1.0f + x);
  if (op == MIRAGE_TONEMAP_ACES) {
    // Narkowicz's fit of the ACES filmic curve.
    return clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
  }
  return min(x, 1.0f);
}

SHARED_FN float srgb_encode(float x) {
  x = clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

// Linear radiance to display-encoded [0, 1] values.
SHARED_FN vec3 display_transform(vec3 linear, float exposure, int op) {
  vec3 c = linear * exposure;
  return vec3(srgb_encode(tonemap_channel(c.x, op)), srgb_encode(tonemap_channel(c.y, op)),
              srgb_encode(tonemap_channel(c.z, op)));
}

SHARED_END

#endif  // MIRAGE_SHADING_TONEMAP_H
