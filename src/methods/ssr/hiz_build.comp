// Method `ssr`: one level of the hierarchical-Z pyramid. Level 0 is the G-buffer's window depth
// (1, "nothing", outside the screen: the pyramid is a power of two a side), every further
// level the minimum — the nearest depth — of the up to four cells below it.
#include "render/shaders/common.glsl"
#include "methods/ssr/ssr_shared.h"

layout(local_size_x = MIRAGE_SSR_GROUP, local_size_y = MIRAGE_SSR_GROUP) in;

layout(binding = MIRAGE_UNIT_SSR_DEPTH) uniform sampler2D u_depth;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_IN, r32f) uniform readonly image2D u_in;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_OUT, r32f) uniform writeonly image2D u_out;

uniform ivec2 u_out_size;  // the level written
uniform ivec2 u_in_size;   // the level below (level 0: the screen's size)
uniform int u_first;       // 1: write level 0 from the depth buffer

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (at.x >= u_out_size.x || at.y >= u_out_size.y) return;
  if (u_first != 0) {
    bool inside = at.x < u_in_size.x && at.y < u_in_size.y;
    imageStore(u_out, at, vec4(inside ? texelFetch(u_depth, at, 0).r : 1.0f));
    return;
  }
  float nearest = 1.0f;
  for (int i = 0; i < 4; ++i) {
    ivec2 below = 2 * at + ivec2(i & 1, i >> 1);
    if (below.x < u_in_size.x && below.y < u_in_size.y)
      nearest = min(nearest, imageLoad(u_in, below).r);
  }
  imageStore(u_out, at, vec4(nearest));
}
