// Method `ssr`: one level of the hierarchical-Z pyramid, the cells that hold some of the screen
// (hiz_pyramid.h). Level 0 (u_copy) is the depth buffer copied texel for texel: the march reads
// it while the depth buffer is attached for the depth test. Past the screen's edge (past the
// level below's covered cells) the level below counts as 1, "nothing". Each texel holds in
// r the nearest depth and in g the behind limit of the farthest drawn surface
// (ssr_depth_shared.h: the window depth `thickness` behind it; 0 where nothing is drawn); every
// level above holds the minimum of r and the maximum of g of the up to four cells below.
#include "render/shaders/common.glsl"
#include "methods/ssr/ssr_shared.h"
#include "methods/ssr/ssr_depth_shared.h"

layout(local_size_x = MIRAGE_SSR_GROUP, local_size_y = MIRAGE_SSR_GROUP) in;

layout(binding = MIRAGE_UNIT_SSR_DEPTH) uniform sampler2D u_depth;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_IN, rg32f) uniform readonly image2D u_in;
layout(binding = MIRAGE_IMAGE_SSR_LEVEL_OUT, rg32f) uniform writeonly image2D u_out;

uniform ivec2 u_out_size;  // the level written
uniform ivec2 u_in_size;   // the level below (level 0: the screen's size)
uniform int u_copy;        // 1: write level 0, the depth buffer's copy
uniform float u_thickness;  // view-depth units
uniform float u_near;
uniform float u_far;

vec2 below(ivec2 at) {
  if (at.x >= u_in_size.x || at.y >= u_in_size.y) return vec2(1.0f, 0.0f);
  return imageLoad(u_in, at).rg;
}

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (at.x >= u_out_size.x || at.y >= u_out_size.y) return;
  if (u_copy != 0) {
    bool inside = at.x < u_in_size.x && at.y < u_in_size.y;
    float d = inside ? texelFetch(u_depth, at, 0).r : 1.0f;
    imageStore(u_out, at, vec4(d, ssr_behind_limit(d, u_thickness, u_near, u_far), 0.0f, 0.0f));
    return;
  }
  vec2 a = below(2 * at), b = below(2 * at + ivec2(1, 0));
  vec2 c = below(2 * at + ivec2(0, 1)), e = below(2 * at + ivec2(1, 1));
  imageStore(u_out, at,
             vec4(min(min(a.x, b.x), min(c.x, e.x)), max(max(a.y, b.y), max(c.y, e.y)), 0.0f, 0.0f));
}
