// The CPU warper of the zexel method (the forward-mapped planar mirror paper, §4.1, after
// McMillan): zexels warped in an occlusion-compatible order, so that a later zexel landing on a
// pixel is never behind an earlier one and no z-buffer is needed. The reference image is cut at
// the epipole (the output camera's centre projected into it) into up to four sheets, each
// traversed toward the epipole when it is positive (in front of the reference camera) and away
// from it when negative; the sheets run on parallel threads (TBB). A z-buffered warper is the
// reference the tests compare it with.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace mirage {

inline constexpr uint32_t kNoZexel = 0xffffffffu;

// A depth-preserving reflection map: per zexel rgb and the distance along its ray (a value of
// zero or at least `sky` marks a zexel that saw nothing), rows from the bottom.
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
  int splat = 1;         // s x s pixels per zexel, centred on where it lands
  bool parallel = true;  // the sheets on parallel threads
};

// Per output pixel (rows from the bottom) the index of the zexel shown there, or kNoZexel.
std::vector<uint32_t> warpOcclusionCompatible(const ZexelMap2D& map, const WarpCamera& in,
                                              const WarpCamera& out, ivec2 size,
                                              const WarpOptions& options);
// The same with a z-buffer: the zexel nearest the output camera wins (any traversal order).
std::vector<uint32_t> warpZBuffered(const ZexelMap2D& map, const WarpCamera& in,
                                    const WarpCamera& out, ivec2 size, int splat);

}  // namespace mirage
