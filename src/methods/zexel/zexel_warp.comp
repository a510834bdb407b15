// Method `zexel`: the GPU warper (a compute shader). One invocation per zexel of one map's level
// moves it by McMillan's warp (zexel_warp_shared.h) into the image seen from the mirrored eye and
// splats it as a square. Two passes make the depth test exact without 64-bit atomics: the first
// keeps, per pixel, the nearest landed distance (atomicMin on its float bits); the second writes
// the index of a zexel whose distance is the one kept (a tie writes either). Zexels that saw
// nothing are directions (δ = 0) and land infinitely far: where they win, the mirror shows the
// sky the reference camera saw; a pixel nothing reaches is an exposure.
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_warp_shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = MIRAGE_BIND_ZEXEL_KEYS) coherent buffer KeyBlock { uint keys[]; };
layout(std430, binding = MIRAGE_BIND_ZEXEL_INDICES) writeonly buffer IndexBlock {
  uint indices[];
};
layout(binding = MIRAGE_UNIT_ZEXEL_MAPS) uniform sampler2DArray u_maps;  // a: distance

uniform int u_pass;         // 0: nearest distances; 1: indices
uniform int u_slot;         // the map's slot this frame (0 or 1)
uniform int u_layer;        // its layer in u_maps
uniform int u_level;        // the level warped (0: full resolution)
uniform int u_width;        // zexels per row at that level
uniform mat4 u_pi;          // the level's pixel matrix (upper 3 x 3)
uniform vec3 u_ci;          // the map's centre of projection
uniform mat4 u_po_inverse;  // the inverse of the output image's pixel matrix (upper 3 x 3)
uniform vec3 u_co;          // the output's: the mirrored eye
uniform ivec2 u_size;       // the output image, pixels
uniform ivec4 u_rect;       // the mirror's pixels lie in [xy, zw): nothing lands usefully outside
uniform int u_splat;        // splat side in pixels; 0: from the warp's magnification
uniform int u_pixel_scale;  // frame pixels per output pixel along a side (--ssaa)

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (texel.x >= u_width || texel.y >= u_width) return;
  vec4 zexel = texelFetch(u_maps, ivec3(texel, u_layer), u_level);
  if (!(zexel.a > 0.0f)) return;  // never written: outside every capture
  mat3 pi = mat3(u_pi), po_inverse = mat3(u_po_inverse);
  vec2 xi = vec2(texel) + 0.5f;
  bool sky = zexel.a >= 0.5f * MISS_DISTANCE;
  float delta = sky ? 0.0f : zexel_disparity_from_distance(pi, xi, zexel.a);
  vec3 o = zexel_warp(po_inverse, pi, u_ci, u_co, delta, xi);
  if (!(o.z > 0.0f)) return;
  float distance = sky ? MISS_DISTANCE : length(u_ci + (pi * vec3(xi, 1.0f)) / delta - u_co);
  uint key = floatBitsToUint(distance);
  int side = u_splat > 0 ? u_splat
                         : zexel_splat_side(po_inverse, pi, u_ci, u_co, delta, xi, o.xy,
                                            MIRAGE_ZEXEL_MAX_SPLAT * u_pixel_scale,
                                            u_pixel_scale);
  // The side x side block of pixels whose centres are nearest the landing point.
  ivec2 first = ivec2(floor(o.xy - 0.5f * float(side - 1)));
  if (any(greaterThanEqual(first, u_rect.zw)) || any(lessThan(first + side, u_rect.xy))) return;
  uint word = zexel_index_word(u_slot, uint(texel.y * u_width + texel.x));
  for (int dy = 0; dy < side; ++dy)
    for (int dx = 0; dx < side; ++dx) {
      ivec2 pixel = first + ivec2(dx, dy);
      if (any(lessThan(pixel, u_rect.xy)) || any(greaterThanEqual(pixel, u_rect.zw))) continue;
      int at = pixel.y * u_size.x + pixel.x;
      if (u_pass == 0)
        atomicMin(keys[at], key);
      else if (keys[at] == key)
        indices[at] = word;
    }
}
