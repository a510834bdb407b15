// Method `ssr`: one level of the hierarchical-Z pyramid. Level 0 (u_copy) is the depth buffer
// copied texel for texel into an r32f image, which the march may read while the depth buffer is
// attached for the depth test; every level above is the minimum — the nearest depth — of the up
// to four cells below it (1, "nothing", past the screen's edge: the pyramid is a power of two a
// side). The pyramid's texture holds levels 1 and up, its level i - 1 being the pyramid's level i.
#include "render/shaders/common.glsl"
#include "methods/ssr/ssr_shared.h"

layout(local_size_x = MIRAGE_SSR_GROUP, local_size_y = MIRAGE_SSR_GROUP) in;

layout(binding = MIRAGE_UNIT_SSR_DEPTH) uniform sampler2D u_depth;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_IN, r32f) uniform readonly image2D u_in;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_OUT, r32f) uniform writeonly image2D u_out;

uniform ivec2 u_out_size;  // the level written
uniform ivec2 u_in_size;   // the level below (level 0: the screen's size)
uniform int u_copy;        // 1: write level 0, the depth buffer's copy

float below(ivec2 at) {
  if (at.x >= u_in_size.x || at.y >= u_in_size.y) return 1.0f;
  return imageLoad(u_in, at).r;
}

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (at.x >= u_out_size.x || at.y >= u_out_size.y) return;
  if (u_copy != 0) {
    imageStore(u_out, at, vec4(texelFetch(u_depth, at, 0).r));
    return;
  }
  float nearest = below(2 * at);
  nearest = min(nearest, below(2 * at + ivec2(1, 0)));
  nearest = min(nearest, below(2 * at + ivec2(0, 1)));
  nearest = min(nearest, below(2 * at + ivec2(1, 1)));
  imageStore(u_out, at, vec4(nearest));
}
