// How much a reflection probe's influence volume weighs at a shaded point, and how overlapping
// probes share a point: the model of Unity's High Definition Render Pipeline (its "Reflection
// probe usage": an influence volume, a blend distance inside its faces, probes ordered by
// importance then by the size of their volume, smaller first). The weight rises linearly from 0 on
// the volume's surface to 1 at the blend distance inside it; walking the ordered probes, each takes
// its weight of what the probes before it left (min(w, 1 - taken)), and what none takes goes to
// the distant environment. Every term is continuous in the point, so a reflection has no step
// where two probes' volumes meet (tests/shading/probe_blend_test.cpp). Shared by the shaders
// (render/shaders/probe_lookup.glsl) and the C++ tests, which call this very code.
#ifndef MIRAGE_SHADING_PROBE_BLEND_H
#define MIRAGE_SHADING_PROBE_BLEND_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// The weight of `inside`, the distance inside a volume's surface (negative outside), for a blend
// distance `blend`: a step at the surface when blend is 0.
SHARED_FN float probe_blend_ramp(float inside, float blend) {
  if (blend <= 0.0f) return inside >= 0.0f ? 1.0f : 0.0f;
  return clamp(inside / blend, 0.0f, 1.0f);
}

// A box influence [bmin, bmax]: the distance to its nearest face.
SHARED_FN float probe_box_weight(vec3 p, vec3 bmin, vec3 bmax, float blend) {
  vec3 below = p - bmin;
  vec3 above = bmax - p;
  float inside = min(min(min(below.x, below.y), below.z), min(min(above.x, above.y), above.z));
  return probe_blend_ramp(inside, blend);
}

// A sphere influence of `radius` about `centre`.
SHARED_FN float probe_sphere_weight(vec3 p, vec3 centre, float radius, float blend) {
  return probe_blend_ramp(radius - length(p - centre), blend);
}

// The share of a probe of weight `weight` when the probes before it took `taken` (in [0, 1]).
SHARED_FN float probe_blend_share(float weight, float taken) {
  return min(weight, 1.0f - taken);
}

SHARED_END

#endif  // MIRAGE_SHADING_PROBE_BLEND_H
