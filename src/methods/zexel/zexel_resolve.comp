// Method `zexel`: what each pixel of the mirror's rectangle shows (zexel_gather_shared.h: the
// blend of the splats covering it, and the nearest one's distance; alpha -1 where none covers
// it), resolved from the warp's cells before the mirror is drawn, which then reads one texel a
// pixel.
//
// Where splats reach one pixel (the default 3 x 3 splats), an invocation resolves a strip of
// u_strip pixels of a row, sliding a window of the 3 x 3 cells around the pixel along it:
// a pixel fetches one new column of three cells instead of nine, and the window's cells are added
// one by one, by name, with no loop and no array (on llvmpipe the gather's loop and an indexed
// array of cells each cost more than the blend's arithmetic itself). Elsewhere (larger or
// magnification-sized splats, --ssaa) an invocation resolves one pixel by the gather's loop.
//
// Defined when the program is built: ZEXEL_REACH and ZEXEL_ALL_COVER (zexel_gather's reach and
// all_cover).
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

layout(local_size_x = MIRAGE_ZEXEL_RESOLVE_GROUP, local_size_y = MIRAGE_ZEXEL_RESOLVE_GROUP) in;

layout(binding = MIRAGE_UNIT_ZEXEL_KEYS) uniform usamplerBuffer u_keys;
layout(binding = MIRAGE_UNIT_ZEXEL_CELLS) uniform usamplerBuffer u_cells;  // x: in u_keys
layout(binding = MIRAGE_IMAGE_ZEXEL_RESOLVED, rgba32f) uniform writeonly imageBuffer u_resolved;

uniform ivec4 u_rect;       // the mirror's pixels lie in [xy, zw): one resolved texel each
uniform int u_margin;       // cells kept around them (zexelCellMargin)
uniform float u_tolerance;  // the blend's relative depth tolerance

// The cell of frame pixel `pixel`; empty beyond the cells kept (a strip at the rectangle's far
// edge looks there).
uvec4 zexel_cell_at(ivec2 pixel) {
  int at = zexel_cell_index(pixel, u_rect, u_margin);
  return at < 0 ? uvec4(MIRAGE_ZEXEL_EMPTY)
                : uvec4(texelFetch(u_keys, at).x, texelFetch(u_cells, at).yzw);
}

#include "methods/zexel/zexel_gather_shared.h"

void resolve(ivec2 pixel, vec4 seen) {
  imageStore(u_resolved, (pixel.y - u_rect.y) * (u_rect.z - u_rect.x) + pixel.x - u_rect.x, seen);
}

#if ZEXEL_REACH == 1

uniform int u_strip;  // pixels a strip (ZexelResolvePass: the row's strips as even as can be)

// The window: w<x><y> is the cell at the pixel + (x - 1, y - 1).
uvec4 w00, w10, w20, w01, w11, w21, w02, w12, w22;

void add(inout ZexelGather g, uvec4 cell, ivec2 pixel, ivec2 offset) {
  zexel_gather_add(g, cell, pixel + offset, pixel, ZEXEL_ALL_COVER != 0, u_tolerance);
}

// zexel_gather(pixel, 1, ...) over the window, in its order (rows from the lowest).
vec4 gather_window(ivec2 pixel) {
  ZexelGather g = zexel_gather_begin();
  add(g, w00, pixel, ivec2(-1, -1));
  add(g, w10, pixel, ivec2(0, -1));
  add(g, w20, pixel, ivec2(1, -1));
  add(g, w01, pixel, ivec2(-1, 0));
  add(g, w11, pixel, ivec2(0, 0));
  add(g, w21, pixel, ivec2(1, 0));
  add(g, w02, pixel, ivec2(-1, 1));
  add(g, w12, pixel, ivec2(0, 1));
  add(g, w22, pixel, ivec2(1, 1));
  return zexel_gather_end(g, u_tolerance);
}

void main() {
  ivec2 first = u_rect.xy + ivec2(int(gl_GlobalInvocationID.x) * u_strip, gl_GlobalInvocationID.y);
  if (any(greaterThanEqual(first, u_rect.zw))) return;
  w00 = zexel_cell_at(first + ivec2(-1, -1));
  w01 = zexel_cell_at(first + ivec2(-1, 0));
  w02 = zexel_cell_at(first + ivec2(-1, 1));
  w10 = zexel_cell_at(first + ivec2(0, -1));
  w11 = zexel_cell_at(first);
  w12 = zexel_cell_at(first + ivec2(0, 1));
  for (int i = 0; i < u_strip; ++i) {
    ivec2 pixel = first + ivec2(i, 0);
    if (pixel.x >= u_rect.z) break;
    w20 = zexel_cell_at(pixel + ivec2(1, -1));
    w21 = zexel_cell_at(pixel + ivec2(1, 0));
    w22 = zexel_cell_at(pixel + ivec2(1, 1));
    resolve(pixel, gather_window(pixel));
    w00 = w10;
    w01 = w11;
    w02 = w12;
    w10 = w20;
    w11 = w21;
    w12 = w22;
  }
}

#else

void main() {
  ivec2 pixel = u_rect.xy + ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, u_rect.zw))) return;
  resolve(pixel, zexel_gather(pixel, ZEXEL_REACH, ZEXEL_ALL_COVER != 0, u_tolerance));
}

#endif
