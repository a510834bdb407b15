// The viewer's output pass: a frame's linear radiance through the display transform of
// shading/tonemap.h (exposure, tone map, sRGB) — the very function `mirage render` applies to
// its PNGs — into the window.
#include "shading/tonemap.h"

layout(binding = 0) uniform sampler2D u_frame;

uniform float u_exposure;
uniform int u_tonemap;

layout(location = 0) out vec4 out_color;

void main() {
  vec3 linear = texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb;
  out_color = vec4(display_transform(linear, u_exposure, u_tonemap), 1.0f);
}
