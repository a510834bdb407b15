// Method `zexel`: a planar mirror shows, at its own pixel, the blend of the splats covering it
// (zexel_gather_shared.h) and the nearest one's distance from the mirrored eye (the distance from
// the real eye through the mirror point, so the reflected ray's length is that minus the eye's
// distance to the mirror point). Where no splat covers it (an exposure) the mirror shows, in this
// order: the farthest zexel landed nearby (the fill: an exposure is background disoccluded by a
// nearer surface, so the farthest of the first zexels met in eight directions stands for it),
// what it showed there the frame before (the paper's no-clear option), or black (the paper's
// cleared colour buffer). The early depth test keeps hidden mirror pixels out of the counts and
// the history.
layout(early_fragment_tests) in;

#include "render/shaders/reflector.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

layout(std430, binding = MIRAGE_BIND_ZEXEL_KEYS) readonly buffer KeyBlock { uint keys[]; };
layout(std430, binding = MIRAGE_BIND_ZEXEL_CELLS) readonly buffer CellBlock {
  uvec4 cells[];  // a cell's words (x: in `keys`)
};
layout(std430, binding = MIRAGE_BIND_ZEXEL_COUNTERS) buffer CounterBlock { uint counters[]; };
layout(binding = MIRAGE_IMAGE_ZEXEL_HISTORY, rgba32f) uniform coherent image2D u_history;

uniform int u_keep;         // 1: exposures keep the last frame's colour (the no-clear option)
uniform int u_fill;         // the fill's search radius in output pixels (0: no fill)
uniform int u_unit;         // frame pixels per output pixel along a side (--ssaa)
uniform ivec4 u_rect;       // the mirror's pixels lie in [xy, zw)
uniform int u_margin;       // cells kept around them: at least the splats' reach and u_unit
// ZEXEL_REACH (defined when the program is built): how far a splat reaches from the pixel it
// landed in; ZEXEL_ALL_COVER: 1 when every splat is 2 ZEXEL_REACH + 1 wide. Constants, so that
// the gather's loops unroll and the coverage test goes where it cannot fail.
uniform float u_tolerance;  // the blend's relative depth tolerance

// No bounds to check: every cell within u_margin of a pixel of u_rect is kept (the gather reads
// within u_reach of the mirror's pixels, the fill's blocks within u_unit of pixels of u_rect).
uint zexel_cell_index_at(ivec2 pixel) {
  ivec2 at = pixel - u_rect.xy + ivec2(u_margin);
  return uint(at.y * (u_rect.z - u_rect.x + 2 * u_margin) + at.x);
}

uvec4 zexel_cell_at(ivec2 pixel) {
  uint at = zexel_cell_index_at(pixel);
  return uvec4(keys[at], cells[at].yzw);
}

#include "methods/zexel/zexel_gather_shared.h"

// The farthest of the first zexels met walking from `pixel` in eight directions, an output pixel
// (u_unit x u_unit frame pixels) a step: rgb and its distance; alpha -1: none.
vec4 farthest_neighbour(ivec2 pixel) {
  const ivec2 steps[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
                                  ivec2(1, 1), ivec2(-1, -1), ivec2(1, -1), ivec2(-1, 1));
  uint best_key = 0u;
  ivec2 best = ivec2(-1);
  for (int d = 0; d < 8; ++d)
    for (int r = 1; r <= u_fill; ++r) {
      ivec2 q = pixel + r * u_unit * steps[d];
      if (any(lessThan(q, u_rect.xy)) || any(greaterThanEqual(q, u_rect.zw))) break;
      // The nearest zexel landed in the block: what the walk meets there (at one sample a pixel
      // the block is the pixel: no loop, which costs the shader even when it runs once).
      uint key = keys[zexel_cell_index_at(q)];
      ivec2 at = q;
      if (u_unit > 1)
        for (int y = 0; y < u_unit; ++y)
          for (int x = 0; x < u_unit; ++x) {
            ivec2 c = q + ivec2(x, y) - ivec2(u_unit / 2);
            uint k = keys[zexel_cell_index_at(c)];
            if (k < key) {
              key = k;
              at = c;
            }
          }
      if (key == MIRAGE_ZEXEL_EMPTY) continue;
      if (key > best_key) {
        best_key = key;
        best = at;
      }
      break;
    }
  if (best.x < 0) return vec4(0.0f, 0.0f, 0.0f, -1.0f);
  return vec4(zexel_cell_color(zexel_cell_at(best)), uintBitsToFloat(best_key));
}

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 seen = zexel_gather(pixel, ZEXEL_REACH, ZEXEL_ALL_COVER != 0, u_tolerance);
  if (seen.a < 0.0f) {
    atomicAdd(counters[MIRAGE_ZEXEL_COUNT_EXPOSED], 1u);
    if (u_fill > 0) seen = farthest_neighbour(pixel);
    if (seen.a < 0.0f)
      seen = u_keep != 0 ? imageLoad(u_history, pixel) : vec4(0.0f, 0.0f, 0.0f, MISS_DISTANCE);
  }
  if (u_keep != 0) imageStore(u_history, pixel, seen);
  float distance = seen.a >= MISS_DISTANCE ? MISS_DISTANCE
                                           : max(seen.a - length(frame.eye.xyz - position), 0.0f);
  return vec4(seen.rgb, distance);
}
