// The zexel method's fill (run by zexel_mirror.frag): what an exposed mirror pixel shows. An
// exposure is background disoccluded by a nearer surface, so the farthest of the first zexels
// met walking from the pixel in eight directions stands for it. Shared by the mirror's shader and
// the C++ tests (fillZexel).
//
// The includer defines, before including this file:
//   uint zexel_key_at(ivec2 pixel);    // the key of frame pixel `pixel`'s cell
//   uvec4 zexel_cell_at(ivec2 pixel);  // its cell
// for every pixel within the mirror's rectangle and `unit` around it.
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_FILL_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_FILL_SHARED_H

#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

SHARED_BEGIN

// The walk's eight directions: right, left, up, down, then the diagonals.
SHARED_FN ivec2 zexel_fill_step(int d) {
  return d == 0   ? ivec2(1, 0)
         : d == 1 ? ivec2(-1, 0)
         : d == 2 ? ivec2(0, 1)
         : d == 3 ? ivec2(0, -1)
         : d == 4 ? ivec2(1, 1)
         : d == 5 ? ivec2(-1, -1)
         : d == 6 ? ivec2(1, -1)
                  : ivec2(-1, 1);
}

// The farthest of the first zexels met walking from `pixel` in eight directions within `fill`
// output pixels (`unit` x `unit` frame pixels a step: --ssaa), inside `rect` ([xy, zw)): rgb and
// its distance; alpha -1: none.
SHARED_FN vec4 zexel_farthest_neighbour(ivec2 pixel, int fill, int unit, ivec4 rect) {
  uint best_key = 0u;
  ivec2 best = ivec2(-1);
  for (int d = 0; d < 8; ++d)
    for (int r = 1; r <= fill; ++r) {
      ivec2 q = pixel + r * unit * zexel_fill_step(d);
      if (q.x < rect.x || q.y < rect.y || q.x >= rect.z || q.y >= rect.w) break;
      // The nearest zexel landed in the block: what the walk meets there (at one sample a pixel
      // the block is the pixel: no loop, which costs the shader even when it runs once).
      uint key = zexel_key_at(q);
      ivec2 at = q;
      if (unit > 1)
        for (int y = 0; y < unit; ++y)
          for (int x = 0; x < unit; ++x) {
            ivec2 c = q + ivec2(x, y) - ivec2(unit / 2);
            uint k = zexel_key_at(c);
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

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_FILL_SHARED_H
