// Method `zexel`: a planar mirror shows, at its own pixel, the zexel the warp left there: its
// colour from the map and its distance from the mirrored eye (the distance from the real eye
// through the mirror point, so the reflected ray's length is that minus the eye's distance to the
// mirror point). Where no zexel landed (an exposure) the mirror shows, in this order: the farthest
// zexel found nearby (the fill: an exposure is background disoccluded by a nearer surface, so the
// farthest of the first zexels met in eight directions stands for it), what it showed there the
// frame before (the paper's no-clear option), or black (the paper's cleared colour buffer). The
// early depth test keeps hidden mirror pixels out of the counts and the history.
layout(early_fragment_tests) in;

#include "render/shaders/reflector.glsl"
#include "methods/zexel/zexel_shared.h"

layout(std430, binding = MIRAGE_BIND_ZEXEL_KEYS) readonly buffer KeyBlock { uint keys[]; };
layout(std430, binding = MIRAGE_BIND_ZEXEL_INDICES) readonly buffer IndexBlock {
  uint indices[];
};
layout(std430, binding = MIRAGE_BIND_ZEXEL_COUNTERS) buffer CounterBlock { uint counters[]; };
layout(binding = MIRAGE_UNIT_ZEXEL_MAPS) uniform sampler2DArray u_maps;
layout(binding = MIRAGE_IMAGE_ZEXEL_HISTORY, rgba32f) uniform coherent image2D u_history;

uniform ivec2 u_layers;   // the maps' layers of slots 0 and 1
uniform int u_level;      // the level warped
uniform int u_width;      // zexels per row at that level
uniform int u_keep;       // 1: exposures keep the last frame's colour (the no-clear option)
uniform int u_fill;       // the fill's search radius in pixels (0: no fill)

// The zexel shown at `at`: its colour from the map and its distance from the mirrored eye.
vec4 zexel_seen(int at) {
  uint word = indices[at];
  int layer = (word & MIRAGE_ZEXEL_SLOT_BIT) != 0u ? u_layers.y : u_layers.x;
  int index = int(word & ~MIRAGE_ZEXEL_SLOT_BIT);
  vec3 color = texelFetch(u_maps, ivec3(index % u_width, index / u_width, layer), u_level).rgb;
  return vec4(color, uintBitsToFloat(keys[at]));
}

// The farthest of the first zexels met walking from `pixel` in eight directions; -1: none.
int farthest_neighbour(ivec2 pixel) {
  const ivec2 steps[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
                                  ivec2(1, 1), ivec2(-1, -1), ivec2(1, -1), ivec2(-1, 1));
  ivec2 size = ivec2(frame.viewport.xy);
  int best = -1;
  uint best_key = 0u;
  for (int d = 0; d < 8; ++d)
    for (int r = 1; r <= u_fill; ++r) {
      ivec2 p = pixel + r * steps[d];
      if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) break;
      int at = p.y * size.x + p.x;
      if (indices[at] == MIRAGE_ZEXEL_EMPTY) continue;
      if (keys[at] > best_key) {
        best_key = keys[at];
        best = at;
      }
      break;
    }
  return best;
}

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int at = pixel.y * int(frame.viewport.x) + pixel.x;
  atomicAdd(counters[0], 1u);
  vec4 seen;
  if (indices[at] != MIRAGE_ZEXEL_EMPTY) {
    seen = zexel_seen(at);
  } else {
    atomicAdd(counters[1], 1u);
    int near = u_fill > 0 ? farthest_neighbour(pixel) : -1;
    if (near >= 0)
      seen = zexel_seen(near);
    else
      seen = u_keep != 0 ? imageLoad(u_history, pixel) : vec4(0.0f, 0.0f, 0.0f, MISS_DISTANCE);
  }
  if (u_keep != 0) imageStore(u_history, pixel, seen);
  float distance = seen.a >= MISS_DISTANCE ? MISS_DISTANCE
                                           : max(seen.a - length(frame.eye.xyz - position), 0.0f);
  return vec4(seen.rgb, distance);
}
