// Method `zexel`: the fill of the exposures the resolve listed (zexel_resolve.comp;
// zexel_fill_shared.h: the farthest of the first zexels met walking from it in eight directions
// stands for it). One invocation an exposure, from the list the
// resolve compacted, so that no lane walks for a pixel that needs no fill (in the mirror's
// fragment shader a block of pixels walked as long as its slowest exposed pixel, however few it
// had).
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

layout(local_size_x = MIRAGE_ZEXEL_FILL_GROUP) in;

layout(binding = MIRAGE_UNIT_ZEXEL_KEYS) uniform usamplerBuffer u_keys;
layout(binding = MIRAGE_UNIT_ZEXEL_CELLS) uniform usamplerBuffer u_cells;  // x: in u_keys
layout(binding = MIRAGE_IMAGE_ZEXEL_RESOLVED, rgba32f) uniform writeonly imageBuffer u_resolved;
layout(std430, binding = MIRAGE_BIND_ZEXEL_EXPOSURES) readonly buffer ExposureBlock {
  uint exposures[];  // MIRAGE_ZEXEL_EXPOSURES_HEADER words, then the pixels
};

uniform int u_fill;     // the search radius in output pixels
uniform int u_unit;     // frame pixels per output pixel along a side (--ssaa)
uniform ivec4 u_rect;   // the mirror's pixels lie in [xy, zw)
uniform int u_margin;   // cells kept around them: at least the splats' reach and u_unit

// No bounds to check: every cell within u_margin of a pixel of u_rect is kept (the walk's
// blocks reach within u_unit of pixels of u_rect).
int zexel_cell_index_at(ivec2 pixel) {
  ivec2 at = pixel - u_rect.xy + ivec2(u_margin);
  return at.y * (u_rect.z - u_rect.x + 2 * u_margin) + at.x;
}

uint zexel_key_at(ivec2 pixel) {
  return texelFetch(u_keys, zexel_cell_index_at(pixel)).x;
}

uvec4 zexel_cell_at(ivec2 pixel) {
  int at = zexel_cell_index_at(pixel);
  return uvec4(texelFetch(u_keys, at).x, texelFetch(u_cells, at).yzw);
}

#include "methods/zexel/zexel_fill_shared.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= exposures[3]) return;
  uint word = exposures[MIRAGE_ZEXEL_EXPOSURES_HEADER + i];
  ivec2 pixel = ivec2(word & 0xFFFFu, word >> 16);
  vec4 found = zexel_farthest_neighbour(pixel, u_fill, u_unit, u_rect);
  if (found.a < 0.0f) return;  // stays an exposure (ZEXEL_UNFILLED)
  imageStore(u_resolved, (pixel.y - u_rect.y) * (u_rect.z - u_rect.x) + pixel.x - u_rect.x,
             vec4(found.rgb, -found.a));
}
