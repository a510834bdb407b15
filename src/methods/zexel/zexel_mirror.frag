// Method `zexel`: a planar mirror shows, at its own pixel, the blend of the splats covering it
// (zexel_gather_shared.h: resolved before the draw by zexel_resolve.comp, or gathered here where
// ZEXEL_GATHER_IN_MIRROR is defined, with ZEXEL_REACH and ZEXEL_ALL_COVER) and the nearest one's
// distance from the mirrored eye (the distance from the real eye through the mirror point, so
// the reflected ray's length is that minus the eye's distance to the mirror point). Where no
// splat covers it (an exposure) the mirror shows, in this order: the farthest zexel landed nearby
// (the fill, zexel_fill_shared.h), what it showed there the frame before (the paper's no-clear
// option), or black (the paper's cleared colour buffer). The fill runs here, for the visible
// exposures only: the mirror's rectangle holds pixels the mirror does not cover, often in large
// regions no zexel reaches, where a walk would go its whole length in all eight directions. The
// early depth test keeps hidden mirror pixels out of the fill, the counts and the history.
layout(early_fragment_tests) in;

#include "render/shaders/reflector.glsl"
#include "methods/zexel/zexel_shared.h"
#include "render/shaders/counter_slots.glsl"
#include "methods/zexel/zexel_splat_shared.h"

// What the resolve left a pixel of the mirror's rectangle; the warp's keys and cells for the
// fill (buffer textures: texel fetches are vector gathers on llvmpipe, storage-buffer loads a loop
// over the lanes).
layout(binding = MIRAGE_UNIT_ZEXEL_RESOLVED) uniform samplerBuffer u_resolved;
layout(binding = MIRAGE_UNIT_ZEXEL_KEYS) uniform usamplerBuffer u_keys;
layout(binding = MIRAGE_UNIT_ZEXEL_CELLS) uniform usamplerBuffer u_cells;  // x: in u_keys
layout(std430, binding = MIRAGE_BIND_ZEXEL_COUNTERS) buffer CounterBlock {
  uint counters[MIRAGE_COUNTER_SLOTS * MIRAGE_COUNTER_SLOT_WORDS];
};
layout(binding = MIRAGE_IMAGE_ZEXEL_HISTORY, rgba32f) uniform coherent image2D u_history;

uniform int u_keep;    // 1: exposures keep the last frame's colour (the no-clear option)
uniform int u_fill;    // the fill's search radius in output pixels (0: no fill)
uniform int u_unit;    // frame pixels per output pixel along a side (--ssaa)
uniform ivec4 u_rect;  // the mirror's pixels lie in [xy, zw)
uniform int u_margin;  // cells kept around them: at least the splats' reach and u_unit
#ifdef ZEXEL_GATHER_IN_MIRROR
uniform float u_tolerance;  // the blend's relative depth tolerance
#endif

// No bounds to check: every cell within u_margin of a pixel of u_rect is kept (the fill's blocks
// reach within u_unit of pixels of u_rect).
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
#ifdef ZEXEL_GATHER_IN_MIRROR
#include "methods/zexel/zexel_gather_shared.h"
#endif

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#ifdef ZEXEL_GATHER_IN_MIRROR
  vec4 seen = zexel_gather(pixel, ZEXEL_REACH, ZEXEL_ALL_COVER != 0, u_tolerance);
#else
  vec4 seen =
      texelFetch(u_resolved, (pixel.y - u_rect.y) * (u_rect.z - u_rect.x) + pixel.x - u_rect.x);
#endif
  if (seen.a < 0.0f) {
    atomicAdd(counters[counter_slot() + MIRAGE_ZEXEL_COUNT_EXPOSED], 1u);
    if (u_fill > 0) seen = zexel_farthest_neighbour(pixel, u_fill, u_unit, u_rect);
    if (seen.a < 0.0f)
      seen = u_keep != 0 ? imageLoad(u_history, pixel) : vec4(0.0f, 0.0f, 0.0f, MISS_DISTANCE);
  }
  if (u_keep != 0) imageStore(u_history, pixel, seen);
  float distance = seen.a >= MISS_DISTANCE ? MISS_DISTANCE
                                           : max(seen.a - length(frame.eye.xyz - position), 0.0f);
  return vec4(seen.rgb, distance);
}
