// Method `zexel`: a planar mirror shows, at its own pixel, the blend of the splats covering it
// (zexel_gather_shared.h, resolved before the draw by zexel_resolve.comp) and the nearest one's
// distance from the mirrored eye (the distance from the real eye through the mirror point, so
// the reflected ray's length is that minus the eye's distance to the mirror point). Where no
// splat covers it (an exposure) the mirror shows, in this order: the farthest zexel landed nearby
// (the fill, zexel_fill.comp), what it showed there the frame before (the paper's no-clear
// option), or black (the paper's cleared colour buffer). The early depth test keeps hidden mirror
// pixels out of the counts and the history.
layout(early_fragment_tests) in;

#include "render/shaders/reflector.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

// What the resolve and the fill left a pixel of the mirror's rectangle (zexel_resolved_*).
layout(binding = MIRAGE_UNIT_ZEXEL_RESOLVED) uniform samplerBuffer u_resolved;
layout(std430, binding = MIRAGE_BIND_ZEXEL_COUNTERS) buffer CounterBlock { uint counters[]; };
layout(binding = MIRAGE_IMAGE_ZEXEL_HISTORY, rgba32f) uniform coherent image2D u_history;

uniform int u_keep;    // 1: exposures keep the last frame's colour (the no-clear option)
uniform ivec4 u_rect;  // the mirror's pixels lie in [xy, zw)

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 seen =
      texelFetch(u_resolved, (pixel.y - u_rect.y) * (u_rect.z - u_rect.x) + pixel.x - u_rect.x);
  if (zexel_resolved_exposed(seen.a)) {
    atomicAdd(counters[MIRAGE_ZEXEL_COUNT_EXPOSED], 1u);
    if (zexel_resolved_filled(seen.a))
      seen.a = -seen.a;
    else
      seen = u_keep != 0 ? imageLoad(u_history, pixel) : vec4(0.0f, 0.0f, 0.0f, MISS_DISTANCE);
  }
  if (u_keep != 0) imageStore(u_history, pixel, seen);
  float distance = seen.a >= MISS_DISTANCE ? MISS_DISTANCE
                                           : max(seen.a - length(frame.eye.xyz - position), 0.0f);
  return vec4(seen.rgb, distance);
}
