// The viewer's output pass: a frame's linear radiance through the display transform of
// shading/tonemap.h (exposure, tone map, sRGB) — the very function `mirage render` applies to
// its PNGs — into the window; with a reference, the ray-traced image right of a split line (all
// of the frame to flip to it, none of it for the method alone) and, with u_heatmap, the method's
// error against it as the reports' heat map (shading/heatmap.h) where the method shows.
//
// Two programs from this file: the method alone, and (VIEWER_TRUTH) with the reference. On
// llvmpipe the reference's code costs even where a uniform branch skips it (7.2 against 3.3 ms
// a frame at 720x512: the filtered fetch runs for every pixel), so the plain one has none of it.
#include "shading/tonemap.h"

layout(binding = 0) uniform sampler2D u_frame;

uniform float u_exposure;
uniform int u_tonemap;
uniform int u_ssaa;  // --ssaa N: the frame's N x N texels per window pixel, averaged in linear

// The window pixel's radiance: the mean of its block of frame texels (core/supersample's box).
vec3 frame_radiance() {
  const ivec2 first = ivec2(gl_FragCoord.xy) * u_ssaa;
  vec3 sum = vec3(0.0f);
  for (int j = 0; j < u_ssaa; ++j)
    for (int i = 0; i < u_ssaa; ++i) sum += texelFetch(u_frame, first + ivec2(i, j), 0).rgb;
  return sum / float(u_ssaa * u_ssaa);
}

layout(location = 0) out vec4 out_color;

#ifndef VIEWER_TRUTH

void main() {
  out_color = vec4(display_transform(frame_radiance(), u_exposure, u_tonemap), 1.0f);
}

#else

#include "shading/heatmap.h"

layout(binding = 1) uniform sampler2D u_truth;  // the reference, at its own (reduced) size

uniform float u_split;  // the reference shows right of this many pixels from the left
uniform int u_line;     // draw the split line
uniform int u_heatmap;  // the error instead of the method's frame where the method shows
uniform float u_heat_max;
uniform vec2 u_size;

void main() {
  const vec3 method = display_transform(frame_radiance(), u_exposure, u_tonemap);
  const vec3 truth = display_transform(textureLod(u_truth, gl_FragCoord.xy / u_size, 0.0f).rgb,
                                       u_exposure, u_tonemap);
  vec3 c = gl_FragCoord.x >= u_split ? truth : method;
  if (gl_FragCoord.x < u_split && u_heatmap != 0)
    c = magma(display_error(method, truth) / u_heat_max);
  if (u_line != 0 && abs(gl_FragCoord.x - u_split) < 1.0f) c = vec3(1.0f);
  out_color = vec4(c, 1.0f);
}

#endif
