// The lower bounds that let the curved reflectors' inverse warp (zexel_inverse_shared.h) cross
// empty stretches of an epipolar line in one read: a mip chain of the depth-preserving cube map's
// distances in which a texel of level L ≥ ZEXEL_BOUND_FIRST_LEVEL holds at most the distance the
// search could read (bilinear, level 0) anywhere near it. Shared by the pyramid's build
// (zexel_distance_pyramid.comp), the CPU copy (zexel_cube_map.cpp) and the search.
//
// Level L is built in two steps: M_L, the least level-0 distance among the texels it covers
// (2:1 reductions), then the bound B_L, the least M_L within ZEXEL_BOUND_DILATION texels of
// level L, neighbours across a face's edge found by direction. The search reads B_L
// bilinearly at the middle of a stretch of s steps and crosses the stretch when the ray stays
// nearer the centre than that bound all along it. Why that is safe, in a face's coordinates
// x ∈ [−1, 1] (N texels across, a level-L texel 2^(L+1)/N wide), where an angle θ spans at most
// 3θ (the gnomonic map's steepest point, a face's corner: dr/dθ = 1 + r², r² = 2):
//   - a bilinear read of B_L mixes texels whose extent lies within half a level-L texel of the
//     read point, and a bilinear distance at level 0 mixes level-0 texels within one level-0
//     texel of where it is read;
//   - a stretch of s steps of at most one level-0 texel's angle (π / 2N) reaches, from its
//     middle, 3 s π / 4N in face coordinates;
//   - so each texel mixed covers every level-0 distance of the stretch when the dilation E
//     (ZEXEL_BOUND_DILATION level-L texels) satisfies E ≥ 1/2 + 3 s π / (8 · 2^L) + 2^−L.
//     With s = 2^(L−1) steps that is E ≥ 1.09 + 2^−L: 1.34 at level 2, the first with s ≥ 2.
//     E = 2 leaves the margin for neighbours across a face's edge: found by direction through
//     the face's plane extended, k texels beyond the edge land k / (1 + 2k/w) texels into the
//     next face of width w, 1.33 for k = 2 at w = 8 (ZEXEL_BOUND_LEAST_TEXELS).
// The tests check the claim where it matters: a search with the bounds finds the very hits of
// one without them (ZexelInverseWarp.*, ZexelCurvedImages.*).
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_BOUNDS_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_BOUNDS_SHARED_H

#include "shading/cubemap.h"
#include "shading/glsl_compat.h"
#include "shading/shading.h"

#define ZEXEL_BOUND_FIRST_LEVEL 2  // the finest level whose bound crosses a stretch
#define ZEXEL_BOUND_DILATION 2     // level-L texels around a texel that its bound covers
// The coarsest level the search reads has at least this many texels across a face (above).
#define ZEXEL_BOUND_LEAST_TEXELS 8

SHARED_BEGIN

// A stored distance at least this large is the sky: a sky texel stores MISS_DISTANCE (1e30),
// and filtering towards one with any weight above 1e-10 lands above this too, far beyond any
// scene's distances.
SHARED_CONST float ZEXEL_SKY_DISTANCE = 1.0e-10f * MISS_DISTANCE;

// The steps a read of level `level` crosses, for steps of `step` radians on a map whose level-0
// texel spans `texel_angle` at a face's centre: 2^(level−1) texels' angle (0 below the first
// level).
SHARED_FN int zexel_bound_span(int level, float texel_angle, float step) {
  if (level < ZEXEL_BOUND_FIRST_LEVEL) return 0;
  return int(floor(float(1 << (level - 1)) * texel_angle / max(step, 1.0e-30f)));
}

// The coarsest level the search reads on a map of `face_size` texels (0: none).
SHARED_FN int zexel_bound_top_level(int face_size) {
  int top = 0;
  while ((face_size >> (top + 1)) >= ZEXEL_BOUND_LEAST_TEXELS) top += 1;
  return top >= ZEXEL_BOUND_FIRST_LEVEL ? top : 0;
}

#ifdef ZEXEL_BOUNDS_BUILD
// B_L of texel `texel` of face `face` at level `level` (a face `width` texels wide there):
// the least M_L within ZEXEL_BOUND_DILATION texels. An includer that builds the bounds defines
// ZEXEL_BOUNDS_BUILD and, before including this file,
//   float zexel_reduced_distance(int layer, vec3 direction, int level);  // M_L at the texel
//       holding `direction` (nearest), on the face the direction points to
SHARED_FN float zexel_bound_texel(int layer, int face, ivec2 texel, int level, int width) {
  float least = 3.0e38f;
  for (int j = -ZEXEL_BOUND_DILATION; j <= ZEXEL_BOUND_DILATION; ++j)
    for (int i = -ZEXEL_BOUND_DILATION; i <= ZEXEL_BOUND_DILATION; ++i) {
      vec2 st = (vec2(float(texel.x + i), float(texel.y + j)) + 0.5f) / float(width);
      least = min(least, zexel_reduced_distance(layer, cube_direction(face, st), level));
    }
  return least;
}
#endif

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_BOUNDS_SHARED_H
