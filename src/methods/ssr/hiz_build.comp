// Method `ssr`: one level of the hierarchical-Z pyramid. Level 0 (u_copy) is the depth buffer
// copied texel for texel into an rg32f image, which the march may read while the depth buffer is
// attached for the depth test; every level above holds in r the minimum — the nearest depth — of
// the up to four cells below it (1, "nothing", past the screen's edge: the pyramid is a power of
// two a side) and in g the maximum of their drawn depths (the farthest surface; 0 where nothing
// is drawn). The pyramid's texture holds levels 1 and up, its level i - 1 being the pyramid's
// level i.
#include "render/shaders/common.glsl"
#include "methods/ssr/ssr_shared.h"

layout(local_size_x = MIRAGE_SSR_GROUP, local_size_y = MIRAGE_SSR_GROUP) in;

layout(binding = MIRAGE_UNIT_SSR_DEPTH) uniform sampler2D u_depth;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_IN, rg32f) uniform readonly image2D u_in;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_OUT, rg32f) uniform writeonly image2D u_out;

uniform ivec2 u_out_size;  // the level written
uniform ivec2 u_in_size;   // the level below (level 0: the screen's size)
uniform int u_copy;        // 1: write level 0, the depth buffer's copy

vec2 below(ivec2 at) {
  if (at.x >= u_in_size.x || at.y >= u_in_size.y) return vec2(1.0f, 0.0f);
  return imageLoad(u_in, at).rg;
}

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (at.x >= u_out_size.x || at.y >= u_out_size.y) return;
  if (u_copy != 0) {
    float d = texelFetch(u_depth, at, 0).r;
    imageStore(u_out, at, vec4(d, d < 1.0f ? d : 0.0f, 0.0f, 0.0f));
    return;
  }
  vec2 a = below(2 * at), b = below(2 * at + ivec2(1, 0));
  vec2 c = below(2 * at + ivec2(0, 1)), e = below(2 * at + ivec2(1, 1));
  imageStore(u_out, at,
             vec4(min(min(a.x, b.x), min(c.x, e.x)), max(max(a.y, b.y), max(c.y, e.y)), 0.0f, 0.0f));
}
