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
// weak ones decide. With tolerance 0 the pixel shows the nearest splat covering it, strong or
// weak (the paper's resolution; splats at the very same distance average).
// One pass: a splat joins while it is within the tolerance of the front met so far, and the
// front only moves nearer, so joins chain — a splat met early may end up to (1 + tolerance)^(n-1)
// behind the final front, n the splats that cover the pixel (at most (2 reach + 1)^2: 9 for
// 3 x 3 splats, 17 % at the default 2 %), never more (ZexelBlend.*).
//
// The pass in three steps, so that a shader holding the cells itself (zexel_resolve.comp's
// window) adds them one by one: the running blends (strong, weak: rgb weighted, w the front's
// distance, -1 none yet; and their weights), a cell added, the result.
struct ZexelGather {
  vec4 strong;
  vec4 weak;
  float strong_weights;
  float weak_weights;
};

SHARED_FN ZexelGather zexel_gather_begin() {
  ZexelGather g;
  g.strong = vec4(0.0f, 0.0f, 0.0f, -1.0f);
  g.weak = vec4(0.0f, 0.0f, 0.0f, -1.0f);
  g.strong_weights = 0.0f;
  g.weak_weights = 0.0f;
  return g;
}

// Adds to pixel `pixel`'s gather the splat of `cell`, the cell of pixel `at`.
SHARED_FN void zexel_gather_add(SHARED_INOUT(ZexelGather) g, uvec4 cell, ivec2 at, ivec2 pixel,
                                bool all_cover, float tolerance) {
  if (cell.x == MIRAGE_ZEXEL_EMPTY) return;
  vec2 landed = zexel_cell_landing(cell, at);
  if (!all_cover && !zexel_covers(landed, zexel_cell_side(cell), pixel)) return;
  float w = zexel_weight(vec2(pixel) + 0.5f, landed, zexel_cell_falloff(cell));
  // One blend_add on whichever blend the splat joins (selects, not branches: a shader runs both
  // sides of a branch its lanes disagree on).
  bool is_strong = w >= ZEXEL_WEIGHT_STRONG;
  vec4 blend = is_strong ? g.strong : g.weak;
  float weights = is_strong ? g.strong_weights : g.weak_weights;
  zexel_blend_add(blend, weights, uintBitsToFloat(cell.x), w, zexel_cell_color(cell), tolerance);
  g.strong = is_strong ? blend : g.strong;
  g.strong_weights = is_strong ? weights : g.strong_weights;
  g.weak = is_strong ? g.weak : blend;
  g.weak_weights = is_strong ? g.weak_weights : weights;
}

SHARED_FN vec4 zexel_gather_end(ZexelGather g, float tolerance) {
  // The nearest alone: a weak splat nearer than every strong one takes the pixel.
  if (tolerance == 0.0f && g.weak.w >= 0.0f && (g.strong.w < 0.0f || g.weak.w < g.strong.w))
    return vec4(vec3(g.weak) / g.weak_weights, g.weak.w);
  if (g.strong.w < 0.0f)
    return g.weak.w < 0.0f ? g.weak : vec4(vec3(g.weak) / g.weak_weights, g.weak.w);
  vec4 strong = g.strong;
  float strong_weights = g.strong_weights;
  if (g.weak.w >= 0.0f && zexel_in_front(g.weak.w, strong.w, tolerance) &&
      zexel_in_front(strong.w, g.weak.w, tolerance)) {
    strong = vec4(vec3(strong) + vec3(g.weak), min(strong.w, g.weak.w));
    strong_weights += g.weak_weights;
  }
  return vec4(vec3(strong) / strong_weights, strong.w);
}

SHARED_FN vec4 zexel_gather(ivec2 pixel, int reach, bool all_cover, float tolerance) {
  ZexelGather g = zexel_gather_begin();
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      ivec2 at = pixel + ivec2(dx, dy);
      zexel_gather_add(g, zexel_cell_at(at), at, pixel, all_cover, tolerance);
    }
  return zexel_gather_end(g, tolerance);
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_GATHER_SHARED_H
