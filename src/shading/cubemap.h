// Cube-map addressing as the OpenGL specification defines it (4.5 core, table 8.19), so that
// the C++ ray tracer samples the same texel for a direction as the GPU does, and captures
// render each face with the orientation that the sampler expects.
#ifndef MIRAGE_SHADING_CUBEMAP_H
#define MIRAGE_SHADING_CUBEMAP_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// Face order: +X, -X, +Y, -Y, +Z, -Z (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face).
// Returns the face of direction d and its (s, t) in [0, 1]^2; t = 0 is the first row in memory.
SHARED_FN int cube_face_st(vec3 d, SHARED_OUT(vec2) st) {
  vec3 a = abs(d);
  int face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0.0f ? 0 : 1;
    ma = a.x;
    sc = d.x >= 0.0f ? -d.z : d.z;
    tc = -d.y;
  } else if (a.y >= a.z) {
    face = d.y >= 0.0f ? 2 : 3;
    ma = a.y;
    sc = d.x;
    tc = d.y >= 0.0f ? d.z : -d.z;
  } else {
    face = d.z >= 0.0f ? 4 : 5;
    ma = a.z;
    sc = d.z >= 0.0f ? d.x : -d.x;
    tc = -d.y;
  }
  st = vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f));
  return face;
}

// The (unnormalised) direction through (s, t) of a face: the inverse of cube_face_st.
SHARED_FN vec3 cube_direction(int face, vec2 st) {
  float sc = 2.0f * st.x - 1.0f;
  float tc = 2.0f * st.y - 1.0f;
  if (face == 0) return vec3(1.0f, -tc, -sc);
  if (face == 1) return vec3(-1.0f, -tc, sc);
  if (face == 2) return vec3(sc, 1.0f, tc);
  if (face == 3) return vec3(sc, -1.0f, -tc);
  if (face == 4) return vec3(sc, -tc, 1.0f);
  return vec3(-sc, -tc, -1.0f);
}

SHARED_END

#endif  // MIRAGE_SHADING_CUBEMAP_H
