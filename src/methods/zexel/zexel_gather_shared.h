// The zexel method's blend (zexel_splat_shared.h): what a mirror pixel shows, gathered from the
// cells whose splats cover it. Shared by zexel_mirror.frag and the C++ tests.
//
// The includer defines, before including this file:
//   uvec4 zexel_cell_at(ivec2 pixel);  // the cell of frame pixel `pixel` (x: MIRAGE_ZEXEL_EMPTY
//                                      // where no zexel landed, and outside the cells kept)
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_GATHER_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_GATHER_SHARED_H

#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

SHARED_BEGIN

// One running blend of the gather: its front distance (-1: none yet), weighted colour, weights.
// A candidate within the relative `tolerance` of the front joins it; one nearer than that starts
// it afresh; one farther is left out.
SHARED_FN void zexel_blend_add(SHARED_INOUT(vec4) blend, SHARED_INOUT(float) weights,
                               float distance, float w, vec3 color, float tolerance) {
  bool nearer = blend.w < 0.0f || !zexel_in_front(blend.w, distance, tolerance);
  bool joins = nearer || zexel_in_front(distance, blend.w, tolerance);
  float keep = nearer ? 0.0f : 1.0f, add = joins ? w : 0.0f;
  blend = joins ? vec4(keep * vec3(blend) + add * color, nearer ? distance : min(blend.w, distance))
                : blend;
  weights = keep * weights + add;
}

// Pixel `pixel`'s blend of the splats covering it (rgb) and the distance of the nearest (alpha;
// -1 where none covers it: an exposure), in one pass over the cells within `reach` (the largest
// splat side / 2: a splat reaches that many pixels from the pixel it landed in), row by row;
// `all_cover`: every splat is `2 reach + 1` wide (fixed odd sides), so each one within the reach
// covers the pixel.
// Visibility follows the kernels: splats whose kernel is strong at the pixel (at least
// ZEXEL_WEIGHT_STRONG) decide the front and blend; weak ones — a splat's rim far from where it
// landed — join that blend within the tolerance but never hide it (so a nearer surface's splats
// do not fatten it over the surface behind); only where no strong splat covers the pixel do the
// weak ones decide. (A splat met early may stay in the blend while up to twice the tolerance
// behind its front: the price of one pass.)
SHARED_FN vec4 zexel_gather(ivec2 pixel, int reach, bool all_cover, float tolerance) {
  vec4 strong = vec4(0.0f, 0.0f, 0.0f, -1.0f), weak = vec4(0.0f, 0.0f, 0.0f, -1.0f);
  float strong_weights = 0.0f, weak_weights = 0.0f;
  vec2 centre = vec2(pixel) + 0.5f;
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      ivec2 at = pixel + ivec2(dx, dy);
      uvec4 cell = zexel_cell_at(at);
      if (cell.x == MIRAGE_ZEXEL_EMPTY) continue;
      vec2 landed = zexel_cell_landing(cell, at);
      if (!all_cover && !zexel_covers(landed, zexel_cell_side(cell), pixel)) continue;
      float w = zexel_weight(centre, landed, zexel_cell_falloff(cell));
      // One blend_add on whichever blend the splat joins (selects, not branches: a shader runs
      // both sides of a branch its lanes disagree on).
      bool is_strong = w >= ZEXEL_WEIGHT_STRONG;
      vec4 blend = is_strong ? strong : weak;
      float weights = is_strong ? strong_weights : weak_weights;
      zexel_blend_add(blend, weights, uintBitsToFloat(cell.x), w, zexel_cell_color(cell),
                      tolerance);
      strong = is_strong ? blend : strong;
      strong_weights = is_strong ? weights : strong_weights;
      weak = is_strong ? weak : blend;
      weak_weights = is_strong ? weak_weights : weights;
    }
  if (strong.w < 0.0f) return weak.w < 0.0f ? weak : vec4(vec3(weak) / weak_weights, weak.w);
  if (weak.w >= 0.0f && zexel_in_front(weak.w, strong.w, tolerance) &&
      zexel_in_front(strong.w, weak.w, tolerance)) {
    strong = vec4(vec3(strong) + vec3(weak), min(strong.w, weak.w));
    strong_weights += weak_weights;
  }
  return vec4(vec3(strong) / strong_weights, strong.w);
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_GATHER_SHARED_H
