// What the zexel method's warp reads, as the CPU sees it: a map's levels and cameras, and how the
// zexels become pixels (the uniforms of zexel_warp.comp).
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace mirage {

inline constexpr uint32_t kNoZexel = 0xffffffffu;  // MIRAGE_ZEXEL_EMPTY: a key nothing reached
inline constexpr int kMaxAutoSplat = 8;            // as MIRAGE_ZEXEL_MAX_SPLAT

// One level of a depth-preserving reflection map: per zexel rgb and the distance along its ray
// (zero: never written; at least `sky`: saw nothing, a direction that lands infinitely far), rows
// from the bottom.
struct ZexelMap2D {
  int width = 0, height = 0;
  std::vector<vec4> texels;
  float sky = 1.0e29f;
};

// A camera as the warp sees it: its pixel matrix (zexel_warp_shared.h) and centre.
struct WarpCamera {
  mat3 p{1.0f};
  vec3 c{0.0f};
};

// A map to warp: its levels, level 0 first (each half the one before, as zexel_parent builds
// them; those a warp does not read may be empty), its side at level 0 and its camera there.
struct ZexelWarpSource {
  const ZexelMap2D* levels = nullptr;
  int level_count = 1;
  int width = 0;
  WarpCamera camera;
};

struct ZexelSplatOptions {
  int splat = 3;       // side of the square splat in frame pixels; 0: from the warp's magnification
  int unit = 1;        // frame pixels per output pixel (--ssaa): automatic splats in whole ones
  ivec4 rect{0};       // the mirror's pixels, [xy, zw) within the image: the only ones shown
  int tile_level = 0;  // the tiles' level (zexel_splat_shared.h)
  int finest = 0;      // the finest level a tile may warp
  bool lod = true;     // false: every tile warps `finest`
  float goal = 2.0f;   // the largest landing gap a level may leave, frame pixels
  float tolerance = 0.02f;  // the blend's relative depth tolerance
};

}  // namespace mirage
