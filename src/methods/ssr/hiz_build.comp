// Method `ssr`: one level of the hierarchical-Z pyramid, the minimum — the nearest depth — of
// the up to four cells below it. Level 0 is the depth buffer itself (read as a texture, 1,
// "nothing", past the screen's edge: the pyramid is a power of two a side); the texture holds
// levels 1 and up, its level i - 1 being the pyramid's level i.
#include "render/shaders/common.glsl"
#include "methods/ssr/ssr_shared.h"

layout(local_size_x = MIRAGE_SSR_GROUP, local_size_y = MIRAGE_SSR_GROUP) in;

layout(binding = MIRAGE_UNIT_SSR_DEPTH) uniform sampler2D u_depth;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_IN, r32f) uniform readonly image2D u_in;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_OUT, r32f) uniform writeonly image2D u_out;

uniform ivec2 u_out_size;  // the level written
uniform ivec2 u_in_size;   // the level below (level 0: the screen's size)
uniform int u_first;       // 1: the level below is the depth buffer

float below(ivec2 at) {
  if (at.x >= u_in_size.x || at.y >= u_in_size.y) return 1.0f;
  return u_first != 0 ? texelFetch(u_depth, at, 0).r : imageLoad(u_in, at).r;
}

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (at.x >= u_out_size.x || at.y >= u_out_size.y) return;
  float nearest = below(2 * at);
  nearest = min(nearest, below(2 * at + ivec2(1, 0)));
  nearest = min(nearest, below(2 * at + ivec2(0, 1)));
  nearest = min(nearest, below(2 * at + ivec2(1, 1)));
  imageStore(u_out, at, vec4(nearest));
}
