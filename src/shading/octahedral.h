// Unit vectors as two numbers: the octahedral map (Meyer et al.), which folds the unit sphere
// onto the octahedron |x| + |y| + |z| = 1 and its lower half over the upper, onto the square
// [-1, 1]^2. Method `ssr`'s G-buffer keeps its normals so, which frees two channels of the texel
// for the material and the reflector. Shared by the shaders and the C++ tests (which call this
// very code).
#ifndef MIRAGE_SHADING_OCTAHEDRAL_H
#define MIRAGE_SHADING_OCTAHEDRAL_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// +1 or -1, never 0: the fold of a point on an axis plane stays on the square.
SHARED_FN float octahedral_sign(float x) {
  return x >= 0.0f ? 1.0f : -1.0f;
}

// The point of [-1, 1]^2 of unit (or any non-zero) vector n.
SHARED_FN vec2 octahedral_encode(vec3 n) {
  vec3 o = n / (abs(n.x) + abs(n.y) + abs(n.z));
  if (o.z >= 0.0f) return vec2(o.x, o.y);
  return vec2((1.0f - abs(o.y)) * octahedral_sign(o.x), (1.0f - abs(o.x)) * octahedral_sign(o.y));
}

// The unit vector of point e of [-1, 1]^2: octahedral_decode(octahedral_encode(n)) is n
// normalized, to float rounding.
SHARED_FN vec3 octahedral_decode(vec2 e) {
  vec3 n = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
  float fold = max(-n.z, 0.0f);
  n.x -= fold * octahedral_sign(n.x);
  n.y -= fold * octahedral_sign(n.y);
  return normalize(n);
}

SHARED_END

#endif  // MIRAGE_SHADING_OCTAHEDRAL_H
