// The reflector G-buffer as a screen-space pass reads it (render/reflector_gbuffer.h): per pixel
// the normal facing the viewer (xy, octahedral_encode), a reflector's material + 1 (z) and
// reflector id (w), both 0 elsewhere, beside the frame's depth.
#include "render/shaders/common.glsl"
#include "shading/octahedral.h"

layout(binding = MIRAGE_UNIT_GBUFFER_NORMAL) uniform sampler2D u_gbuffer_normal;
layout(binding = MIRAGE_UNIT_GBUFFER_DEPTH) uniform sampler2D u_gbuffer_depth;
// The reflector id a draw of the pass shades (ReflectorGBuffer::shade: one draw a reflector,
// scissored to it).
uniform int u_gbuffer_reflector;

// Whether the pass shades G-buffer texel g: a pixel of the draw's reflector.
bool gbuffer_shades(vec4 g) { return g.z >= 0.5f && int(g.w + 0.5f) == u_gbuffer_reflector; }

// The world point at window position `window` (pixels, and window depth in z).
vec3 gbuffer_world(vec3 window) {
  vec4 ndc = vec4(window.xy / frame.viewport.xy * 2.0f - 1.0f, window.z * 2.0f - 1.0f, 1.0f);
  vec4 world = frame.inv_view_proj * ndc;
  return world.xyz / world.w;
}

// The screen derivatives of v across the pixel's 2x2 quad, for the filters of the lookups made
// with it. Taken before any lane leaves (uniform control flow). A neighbour on another reflector
// (`surface`: the G-buffer's reflector id) or none says nothing of this one's v: that axis then
// borrows the other's, and with neither both are 0 (a pixel whose quad holds no other pixel of
// its reflector). A pass over the triangles gets them from its helper invocations, which
// extrapolate the same surface.
void gbuffer_differentials(vec3 v, float surface, out vec3 dx, out vec3 dy) {
  dx = dFdxFine(v);
  dy = dFdyFine(v);
  bool x_same = dFdxFine(surface) == 0.0f, y_same = dFdyFine(surface) == 0.0f;
  if (!x_same) dx = y_same ? dy : vec3(0.0f);
  if (!y_same) dy = x_same ? dx : vec3(0.0f);
}
