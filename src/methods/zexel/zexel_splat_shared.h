// How warped zexels become pixels, shared by the warping shader (zexel_warp.comp), the CPU warper
// (zexel_cpu_warper.cpp), the pyramid build and the tests — beyond the forward-mapped planar
// mirror paper, which warps every zexel of a full map and keeps the nearest of those landing on a
// pixel (§4.1).
//
// Tiles and levels (the paper's future work: a mip-map-like hierarchy of the maps). A map is
// warped in tiles: a tile is one zexel of a coarse level T, the block of finer zexels under it.
// Where its neighbours at level T land says how far apart the tile's surface lands — the warped
// surface, at its own depths, not the mirror plane — and the tile warps the coarsest level whose
// zexels land at most `goal` pixels apart. The gap is the largest to any of the four neighbours,
// so a surface seen obliquely and a tile at a depth discontinuity (a silhouette, where the
// surfaces behind are disoccluded) warp finer levels, down to level 0 if need be.
//
// Surface splatting. Every zexel covers a square of pixels (its splat). A pixel shows the blend,
// with Gaussian weights about their landing points, of the splats covering it that lie within a
// depth tolerance of the nearest of them: the front surface, its zexels averaged where they
// overlap rather than the nearest winning outright (which fattened and shifted surfaces towards
// their nearer parts); a farther surface stays out. The warp scatters each zexel to the one pixel
// it lands in — its cell: the nearest zexel landing there, with where it landed, its splat's side,
// its colour and its kernel (zexel_cell) — and the mirror gathers, per pixel, the cells whose
// splats cover it (zexel_gather_shared.h): one atomic per zexel instead of one per covered pixel
// and colour channel. A cell keeps one zexel; zexels landing in the same pixel behind it add
// nothing but, for splats of equal sides, cover no pixel it does not.
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_SPLAT_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_SPLAT_SHARED_H

#include "shading/glsl_compat.h"

#ifndef MIRAGE_GLSL
#include <glm/gtc/packing.hpp>  // packHalf2x16, as GLSL has it
#endif

SHARED_BEGIN

// A tile warps at most this many levels below its own (its loop over zexels stays within 8 x 8).
SHARED_CONST int ZEXEL_TILE_SPAN = 3;
// A gap too large to mean anything (a neighbour landing near infinity, or not a number).
SHARED_CONST float ZEXEL_FAR_GAP = 1.0e30f;
// The kernel's standard deviation: half the surface's spacing (neighbouring kernels then overlap
// enough to sum smoothly) with a third of a pixel for the pixel's own footprint.
SHARED_CONST float ZEXEL_KERNEL_SPACINGS = 0.5f;
SHARED_CONST float ZEXEL_KERNEL_PIXELS = 0.3f;
// The kernel's weights: its peak is 255, its floor 16 (relative: only their ratios count).
SHARED_CONST float ZEXEL_WEIGHT_MAX = 255.0f;
SHARED_CONST float ZEXEL_WEIGHT_MIN = 16.0f;
// A splat whose kernel weighs at least this at a pixel decides what hides what there (the kernel
// within about 1.5 standard deviations of where it landed).
SHARED_CONST float ZEXEL_WEIGHT_STRONG = 80.0f;
// The pyramid: children within 2 % of the nearest's distance are one surface.
SHARED_CONST float ZEXEL_PYRAMID_SAME_DEPTH = 1.02f;

// The pixel matrix of level `level` from level 0's: a level-l zexel (u, v) stands for level 0's
// 2^l x 2^l block centred at 2^l (u, v).
SHARED_FN mat3 zexel_level_matrix(mat3 p0, int level) {
  mat3 p = p0;
  float scale = float(1 << level);
  p[0] *= scale;
  p[1] *= scale;
  return p;
}

// The distance from `from` to what a zexel saw (its disparity `delta`, 0 for the sky: far).
SHARED_FN float zexel_distance_from(mat3 p, vec3 c, vec2 x, float delta, vec3 from, float far) {
  return delta > 0.0f ? length(c + (p * vec3(x, 1.0f)) / delta - from) : far;
}

// The first (lowest) pixel of the side x side block whose centres are nearest `landed`.
SHARED_FN ivec2 zexel_splat_origin(vec2 landed, int side) {
  return ivec2(floor(landed - 0.5f * float(side - 1)));
}

// The pixels a zexel landing in `bounds` may reach: the mirror's `rect` ([xy, zw)) widened by
// half the largest splat side and a pixel.
SHARED_FN vec4 zexel_splat_bounds(ivec4 rect, int largest_side) {
  float reach = float(largest_side / 2 + 1);
  return vec4(rect) + vec4(-reach, -reach, reach, reach);
}

// Whether any zexel of a tile can land within `bounds` (u0, v0, u1, v1: the mirror's pixels with
// the splats' reach) of the output image: the tile's rays through level-0 window coordinates
// [lo, hi] of the reference image (pixel matrix `p0`, centre `ci`), none of its zexels nearer than
// `nearest` along them. With A = P_o⁻¹ (c_i − c_o) and B = P_o⁻¹ P_i x_i, a zexel lands at the
// homogeneous δ A + B (eq. 3), δ in [0, δ_max] (0: the sky), and it is within the bounds where
// four linear forms are non-negative (x − u0 z, u1 z − x, likewise in v; together they imply
// z ≥ 0). A form negative at both ends of δ for the four corner rays is negative for every zexel
// of the tile (it is linear in δ and in x_i): the tile lands outside.
SHARED_FN bool zexel_tile_visible(mat3 po_inverse, mat3 p0, vec3 ci, vec3 co, vec2 lo, vec2 hi,
                                  float nearest, vec4 bounds) {
  vec3 b00 = po_inverse * (p0 * vec3(lo.x, lo.y, 1.0f));
  vec3 b10 = po_inverse * (p0 * vec3(hi.x, lo.y, 1.0f));
  vec3 b01 = po_inverse * (p0 * vec3(lo.x, hi.y, 1.0f));
  vec3 b11 = po_inverse * (p0 * vec3(hi.x, hi.y, 1.0f));
  float longest =
      max(max(length(p0 * vec3(lo.x, lo.y, 1.0f)), length(p0 * vec3(hi.x, lo.y, 1.0f))),
          max(length(p0 * vec3(lo.x, hi.y, 1.0f)), length(p0 * vec3(hi.x, hi.y, 1.0f))));
  vec3 a = (longest / nearest) * (po_inverse * (ci - co));  // δ_max A
  for (int k = 0; k < 4; ++k) {
    // The form's coefficients on (x, y, z).
    vec3 f = k == 0   ? vec3(1.0f, 0.0f, -bounds.x)
             : k == 1 ? vec3(-1.0f, 0.0f, bounds.z)
             : k == 2 ? vec3(0.0f, 1.0f, -bounds.y)
                      : vec3(0.0f, -1.0f, bounds.w);
    float fa = dot(f, a);
    float f00 = dot(f, b00), f10 = dot(f, b10), f01 = dot(f, b01), f11 = dot(f, b11);
    if (max(max(f00, f10), max(f01, f11)) < 0.0f &&
        max(max(f00 + fa, f10 + fa), max(f01 + fa, f11 + fa)) < 0.0f)
      return false;
  }
  return true;
}

// The distance in pixels between where a zexel landed (`o`) and where a neighbour did (`n`); -1
// when the neighbour has none (n.z <= 0: outside the map, never written, or behind the camera).
SHARED_FN float zexel_gap(vec3 o, vec3 n) {
  if (!(n.z > 0.0f)) return -1.0f;
  float gap = length(vec2(n.x, n.y) - vec2(o.x, o.y));
  return gap < ZEXEL_FAR_GAP ? gap : ZEXEL_FAR_GAP;
}

// From the gaps to the left, right, lower and upper neighbours (-1: none): x, the largest (what
// the level must close); y, the surface's own spacing — per axis the smaller gap (a
// discontinuity on one side is not the surface), the larger of the two axes. Zero: no neighbour.
SHARED_FN vec2 zexel_spacing(vec4 gaps) {
  float largest = max(max(gaps.x, gaps.y), max(gaps.z, gaps.w));
  float along_x = gaps.x < 0.0f ? gaps.y : (gaps.y < 0.0f ? gaps.x : min(gaps.x, gaps.y));
  float along_y = gaps.z < 0.0f ? gaps.w : (gaps.w < 0.0f ? gaps.z : min(gaps.z, gaps.w));
  return max(vec2(largest, max(along_x, along_y)), vec2(0.0f));
}

// The level a tile of level `tile` warps: the coarsest in [finest, tile] whose zexels land at
// most `goal` pixels apart, given the largest gap measured at the tile's level (halving per level
// finer). Nothing measured: the finest.
SHARED_FN int zexel_tile_level(float largest, int tile, int finest, float goal) {
  if (!(largest > 0.0f)) return finest;
  float halvings = max(ceil(log2(largest / goal)), 0.0f);
  return tile - int(min(halvings, float(tile - finest)));
}

// The kernel's standard deviation in pixels for zexels `spacing` pixels apart.
SHARED_FN float zexel_kernel_sigma(float spacing) {
  float s = ZEXEL_KERNEL_SPACINGS * spacing;
  return sqrt(s * s + ZEXEL_KERNEL_PIXELS * ZEXEL_KERNEL_PIXELS);
}

// The weight of a zexel landed at `landed` in a pixel its splat covers, whose centre is `centre`:
// the kernel of falloff 1 / (2 σ²), never below its floor (every covering splat counts a little).
SHARED_FN float zexel_weight(vec2 centre, vec2 landed, float falloff) {
  vec2 d = centre - landed;
  return clamp(ZEXEL_WEIGHT_MAX * exp(-dot(d, d) * falloff), ZEXEL_WEIGHT_MIN, ZEXEL_WEIGHT_MAX);
}

// Whether a zexel at `distance` is no farther than the relative `tolerance` behind `nearest`.
SHARED_FN bool zexel_in_front(float distance, float nearest, float tolerance) {
  return distance <= nearest * (1.0f + tolerance);
}

// A cell's words, as few as the gather can read (each costs it): x, the nearest landed
// distance's bits (what the warp's atomicMin keeps); y, where it landed within the pixel (12 + 12
// bits) and its splat's side − 1 (8 bits); z, its colour's red and green; w, its blue and its
// kernel's falloff 1 / (2 σ²) (half floats).
SHARED_CONST float ZEXEL_CELL_STEPS = 4096.0f;

SHARED_FN uvec4 zexel_cell(uint key, vec2 landed, int side, vec3 color, float sigma) {
  vec2 at = clamp(floor((landed - floor(landed)) * ZEXEL_CELL_STEPS), vec2(0.0f),
                  vec2(ZEXEL_CELL_STEPS - 1.0f));
  uint where = uint(at.x) | (uint(at.y) << 12) | (uint(clamp(side - 1, 0, 255)) << 24);
  vec3 c = min(color, vec3(65000.0f));  // a half float's range
  return uvec4(key, where, packHalf2x16(vec2(c.x, c.y)),
               packHalf2x16(vec2(c.z, 0.5f / (sigma * sigma))));
}

// Where the zexel of the cell at pixel `cell` landed (the centre of its 1/4096 step).
SHARED_FN vec2 zexel_cell_landing(uvec4 c, ivec2 cell) {
  vec2 at = vec2(float(c.y & 4095u), float((c.y >> 12) & 4095u));
  return vec2(cell) + (at + 0.5f) / ZEXEL_CELL_STEPS;
}

SHARED_FN int zexel_cell_side(uvec4 c) {
  return int(c.y >> 24) + 1;
}

SHARED_FN vec3 zexel_cell_color(uvec4 c) {
  vec2 rg = unpackHalf2x16(c.z);
  return vec3(rg.x, rg.y, unpackHalf2x16(c.w).x);
}

SHARED_FN float zexel_cell_falloff(uvec4 c) {
  return unpackHalf2x16(c.w).y;
}

// Whether a splat of side `side` landed at `landed` covers pixel `pixel`.
SHARED_FN bool zexel_covers(vec2 landed, int side, ivec2 pixel) {
  ivec2 d = pixel - zexel_splat_origin(landed, side);
  return d.x >= 0 && d.y >= 0 && d.x < side && d.y < side;
}

// The index of pixel `pixel`'s cell among the cells of the mirror's pixels `rect` ([xy, zw)) with
// `margin` pixels around them (splats landing there still cover the mirror); -1 outside them.
SHARED_FN int zexel_cell_index(ivec2 pixel, ivec4 rect, int margin) {
  ivec2 at = pixel - ivec2(rect.x, rect.y) + ivec2(margin);
  ivec2 cells = ivec2(rect.z - rect.x, rect.w - rect.y) + ivec2(2 * margin);
  if (at.x < 0 || at.y < 0 || at.x >= cells.x || at.y >= cells.y) return -1;
  return at.y * cells.x + at.x;
}

// A child's colour into its parent's average, if it was written and lies at about the nearest
// child's depth (its distance within `limit`).
SHARED_FN void zexel_add_near_child(vec4 child, float limit, SHARED_INOUT(vec3) sum,
                                    SHARED_INOUT(float) n) {
  if (child.w > 0.0f && child.w <= limit) {
    sum += vec3(child);
    n += 1.0f;
  }
}

// A zexel of the next coarser level from its four children (alpha: the distance, 0 never
// written): the nearest child's distance — a coarse zexel never lets a nearer surface fall
// through — with the colour averaged over the children at about its depth, so that colours do not
// bleed across a silhouette.
SHARED_FN vec4 zexel_parent(vec4 a, vec4 b, vec4 c, vec4 d) {
  float far = 3.0e38f;
  float nearest = min(min(a.w > 0.0f ? a.w : far, b.w > 0.0f ? b.w : far),
                      min(c.w > 0.0f ? c.w : far, d.w > 0.0f ? d.w : far));
  if (!(nearest < far)) return vec4(0.0f);
  float limit = nearest * ZEXEL_PYRAMID_SAME_DEPTH;
  vec3 sum = vec3(0.0f);
  float n = 0.0f;
  zexel_add_near_child(a, limit, sum, n);
  zexel_add_near_child(b, limit, sum, n);
  zexel_add_near_child(c, limit, sum, n);
  zexel_add_near_child(d, limit, sum, n);
  return vec4(sum / n, nearest);
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_SPLAT_SHARED_H
