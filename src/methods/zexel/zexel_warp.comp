// Method `zexel`: the GPU warper (a compute shader). One invocation per zexel of the tiles of one
// map, every level they warp in one dispatch (zexel_tiles.h plans them, finest level first): it
// moves the zexel by McMillan's warp (zexel_warp_shared.h) into the image seen from the mirrored
// eye and leaves it in the cell of the pixel it lands in, with its splat's side and kernel
// (zexel_splat_shared.h; the resolve gathers the splats covering each pixel). Two passes make
// each cell's choice exact without 64-bit atomics: the first keeps the nearest landed distance
// (atomicMin on its float bits), the second writes the rest of the cell for a zexel whose
// distance is the one kept (a tie writes either). Zexels that saw nothing are directions (δ = 0) and land infinitely far: where they are
// in front, the mirror shows the sky the reference camera saw.
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_warp_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

layout(local_size_x = MIRAGE_ZEXEL_GROUP) in;

layout(std430, binding = MIRAGE_BIND_ZEXEL_KEYS) coherent buffer KeyBlock { uint keys[]; };
layout(std430, binding = MIRAGE_BIND_ZEXEL_CELLS) writeonly buffer CellBlock {
  uvec4 cells[];  // a cell's words (x unused: the key is in `keys`)
};
layout(std430, binding = MIRAGE_BIND_ZEXEL_TILES) readonly buffer TileBlock { uvec2 tiles[]; };
layout(binding = MIRAGE_UNIT_ZEXEL_MAPS) uniform sampler2DArray u_maps;  // a: distance

uniform int u_pass;         // 0: the nearest distances; 1: the rest of the cells
uniform int u_layer;        // the map's layer in u_maps
uniform int u_width;        // level 0's zexels per row
uniform int u_finest;       // the level the plan's first tiles warp (its finest)
uniform int u_tile_level;   // the tiles' own level: a tile warping level l is 2^(it - l) a side
uniform ivec4 u_ends;       // per level from the finest, the invocations up to its last zexel
uniform ivec4 u_firsts;     // per level from the finest, its first tile in `tiles`
uniform mat4 u_pi;          // level 0's pixel matrix (upper 3 x 3)
uniform vec3 u_ci;          // the map's centre of projection
uniform mat4 u_po_inverse;  // the inverse of the output image's pixel matrix (upper 3 x 3)
uniform vec3 u_co;          // the output's: the mirrored eye
uniform ivec4 u_rect;       // the mirror's pixels lie in [xy, zw): nothing lands usefully outside
uniform int u_margin;       // cells kept around the mirror's pixels (zexelCellMargin)
uniform int u_splat;        // splat side in pixels; 0: from the warp's magnification
uniform int u_pixel_scale;  // frame pixels per output pixel along a side (--ssaa)

// Warps zexel `texel` of `level` into its cell: pass 0 its distance, pass 1 the rest.
void splat(ivec2 texel, int level, mat3 p, float sigma) {
  if (any(greaterThanEqual(texel, ivec2(max(u_width >> level, 1))))) return;
  vec4 zexel = texelFetch(u_maps, ivec3(texel, u_layer), level);
  if (!(zexel.a > 0.0f)) return;  // never written: outside every capture
  vec2 xi = vec2(texel) + 0.5f;
  bool missed = zexel.a >= 0.5f * MISS_DISTANCE;
  float delta = missed ? 0.0f : zexel_disparity_from_distance(p, xi, zexel.a);
  vec3 o = zexel_warp(mat3(u_po_inverse), p, u_ci, u_co, delta, xi);
  if (!(o.z > 0.0f)) return;
  float distance = zexel_distance_from(p, u_ci, xi, delta, u_co, MISS_DISTANCE);
  int side = u_splat > 0 ? u_splat
                         : zexel_splat_side(mat3(u_po_inverse), p, u_ci, u_co, delta, xi, o.xy,
                                            MIRAGE_ZEXEL_MAX_SPLAT * u_pixel_scale,
                                            u_pixel_scale);
  ivec2 first = zexel_splat_origin(o.xy, side);
  if (any(greaterThanEqual(first, u_rect.zw)) || any(lessThan(first + side, u_rect.xy))) return;
  int at = zexel_cell_index(ivec2(floor(o.xy)), u_rect, u_margin);
  if (at < 0) return;
  uint key = floatBitsToUint(distance);
  if (u_pass == 0) {
    atomicMin(keys[at], key);
  } else if (keys[at] == key) {
    cells[at] = zexel_cell(key, o.xy, side, zexel.rgb, sigma);
  }
}

void main() {
  // This dispatch's zexels, level after level and tile after tile: gl_NumWorkGroups.x groups a
  // row of groups.
  int index = int((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * MIRAGE_ZEXEL_GROUP +
                  gl_LocalInvocationIndex);
  if (index >= u_ends.w) return;
  int i = int(index >= u_ends.x) + int(index >= u_ends.y) + int(index >= u_ends.z);
  int start = i == 0 ? 0 : (i == 1 ? u_ends.x : (i == 2 ? u_ends.y : u_ends.z));
  int level = u_finest + i, span = u_tile_level - level;
  int tile = (index - start) >> (2 * span);
  uvec2 word = tiles[u_firsts[i] + tile];
  int n = 1 << span, k = (index - start) & (n * n - 1);
  ivec2 texel = ivec2(word.x & 0xFFFFu, word.x >> 16) * n + ivec2(k & (n - 1), k >> span);
  splat(texel, level, zexel_level_matrix(mat3(u_pi), level),
        zexel_kernel_sigma(uintBitsToFloat(word.y)));
}
