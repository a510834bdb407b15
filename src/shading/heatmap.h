// The error heat map's colours (magma, perceptually uniform), shared by the reports' heat maps
// (eval/heatmap) and the viewer's error overlay (viewer/display.frag), so that both read alike.
#ifndef MIRAGE_SHADING_HEATMAP_H
#define MIRAGE_SHADING_HEATMAP_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// Nine control points of matplotlib's magma.
SHARED_FN vec3 magma_stop(int i) {
  if (i <= 0) return vec3(0.001f, 0.000f, 0.014f);
  if (i == 1) return vec3(0.110f, 0.066f, 0.296f);
  if (i == 2) return vec3(0.316f, 0.071f, 0.485f);
  if (i == 3) return vec3(0.512f, 0.128f, 0.507f);
  if (i == 4) return vec3(0.716f, 0.215f, 0.475f);
  if (i == 5) return vec3(0.904f, 0.315f, 0.384f);
  if (i == 6) return vec3(0.988f, 0.535f, 0.382f);
  if (i == 7) return vec3(0.996f, 0.780f, 0.520f);
  return vec3(0.987f, 0.991f, 0.750f);
}

// The colour of t in [0, 1] (clamped), the stops interpolated linearly.
SHARED_FN vec3 magma(float t) {
  const float x = clamp(t, 0.0f, 1.0f) * 8.0f;
  const int i = min(int(x), 7);
  return mix(magma_stop(i), magma_stop(i + 1), x - float(i));
}

// The per-pixel error of the heat maps: the mean absolute difference of two display colours.
SHARED_FN float display_error(vec3 a, vec3 b) {
  const vec3 d = abs(a - b);
  return (d.x + d.y + d.z) / 3.0f;
}

SHARED_END

#endif  // MIRAGE_SHADING_HEATMAP_H
