// The CPU warper of the zexel method (the forward-mapped planar mirror paper, §4.1, after
// McMillan): zexels warped in an occlusion-compatible order, so that a later zexel landing on a
// pixel is never behind an earlier one and no z-buffer is needed. The reference image is cut at
// the epipole (the output camera's centre projected into it) into up to four sheets, each
// traversed toward the epipole when it is positive (in front of the reference camera) and away
// from it when negative; the sheets, split further into wedges about the epipole (zexels on
// different epipolar lines never land on one another), run on parallel threads (TBB). A z-buffered
// warper is the reference the tests compare it with.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace mirage {

inline constexpr uint32_t kNoZexel = 0xffffffffu;
inline constexpr int kMaxAutoSplat = 8;  // as MIRAGE_ZEXEL_MAX_SPLAT

// A depth-preserving reflection map: per zexel rgb and the distance along its ray (zero: never
// written; at least `sky`: saw nothing, a direction that lands infinitely far), rows from the
// bottom.
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

struct WarpOptions {
  int splat = 1;         // s x s pixels per zexel, centred on where it lands; 0: from the warp's
                         // magnification (zexel_splat_side), at most kMaxAutoSplat
  bool parallel = true;  // the sheets on parallel threads
  ivec4 rect{0, 0, 1 << 30, 1 << 30};  // only pixels in [xy, zw) are written (a mirror's)
  int wedges = 8;  // each sheet split into this many wedges about the epipole (parallel tasks)
  // Automatic splats in whole output pixels of this many frame pixels, at most kMaxAutoSplat of
  // them (--ssaa).
  int unit = 1;
};

// Per output pixel (rows from the bottom) the index of the zexel shown there, or kNoZexel.
std::vector<uint32_t> warpOcclusionCompatible(const ZexelMap2D& map, const WarpCamera& in,
                                              const WarpCamera& out, ivec2 size,
                                              const WarpOptions& options);
// The same with a z-buffer: the zexel nearest the output camera wins (any traversal order).
std::vector<uint32_t> warpZBuffered(const ZexelMap2D& map, const WarpCamera& in,
                                    const WarpCamera& out, ivec2 size, int splat);

// The distance from `from` to what zexel `index` saw (MISS_DISTANCE for the sky).
float zexelDistance(const ZexelMap2D& map, const WarpCamera& in, uint32_t index, const vec3& from);

}  // namespace mirage
