// A planar mirror's depth-preserving reflection maps (the forward-mapped planar mirror paper, §3
// and §4.1): reference cameras on the hemisphere behind the mirror, each capturing the colour and
// the distance along the ray of the scene in front of it (zexels), in one texture array with a
// mip-map-like hierarchy (the paper's future work: coarser levels for surfaces seen from afar,
// each texel the nearest of its four children with the colours of those at its depth averaged;
// zexel_parent). The hierarchy is built whether or not the warp uses coarser levels: its tiles
// measure their surface on it (zexel_splat_shared.h).
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/method.h"
#include "methods/zexel/zexel_warp_types.h"
#include "render/frame_target.h"

namespace mirage {

// The reference cameras' default spread from the mirror's axis, degrees: with 8 maps along
// mirror-room's walk every measure improved from 20° to 80° (views from the side find their
// maps; docs/zexel-results.md, the hemisphere), as mirror-hall's 64 maps did from 60° to 80°;
// 85° is the parameter's limit.
inline constexpr float kDefaultZexelCone = 80.0f;

struct ZexelMapOptions {
  int size = 512;                  // zexels per side
  int count = 1;                   // maps on the hemisphere
  float cone = kDefaultZexelCone;  // their spread from the pole, degrees
  float fov = 100.0f;              // each reference camera's vertical field of view, degrees
  bool hierarchy = false;   // warp coarser levels where they suffice (the levels are always built)
  bool cpu_copies = false;  // keep every level on the CPU too (the CPU warper)
};

class ZexelMirrorMaps {
 public:
  ZexelMirrorMaps(int mirror, const ZexelMapOptions& options);

  int mirror() const { return mirror_; }
  bool captured() const { return !views_.empty(); }
  const vec3& normal() const { return normal_; }  // the side captured
  int count() const { return int(views_.size()); }
  int levels() const { return maps_.levels(); }
  // Zexels per side at `level` of the hierarchy.
  int width(int level) const { return std::max(options_.size >> level, 1); }
  const View& view(int map) const { return views_[size_t(map)]; }
  const gpu::Texture& texture() const { return maps_; }
  // A map's level on the CPU, rows from the bottom: the levels tiles may be planned on (from
  // ZEXEL_TILE_SPAN) always, every level with cpu_copies (the others are empty). A map's levels
  // follow each other: &cpuMap(map, 0) + level is cpuMap(map, level).
  const ZexelMap2D& cpuMap(int map, int level) const {
    return cpu_[size_t(map) * size_t(levels()) + size_t(level)];
  }
  // A map's level as the warp sees it: its pixel matrix at that level and its centre.
  WarpCamera warpCamera(int map, int level) const;

  // Captures every map for the mirror plane (`point`, unit `normal` towards the eye's side) into
  // `scratch` (size², reused) then the array; `base` shades the other reflectors.
  void capture(FrameContext& frame, const vec3& point, const vec3& normal, FrameTarget& scratch,
               const gpu::Program& base, const gpu::Program& pyramid);

  // The maps a frame seen from `mirrored_eye` warps: the `count` nearest.
  std::vector<int> select(const vec3& mirrored_eye, int count) const;

  // The coarsest level whose zexels at the mirror plane land at most `spacing_goal` pixels apart
  // in `output`, seen through map `map` (at the mirror's centre). Nearer the reference camera than
  // anything it captured, the plane's zexels land the closest together when the mirrored eye is
  // farther from the mirror than the camera: no surface can use a coarser level (the tiles' level).
  int levelFor(int map, const View& output, float spacing_goal) const;

 private:
  void readBack();

  int mirror_;
  ZexelMapOptions options_;
  vec3 point_{0.0f}, normal_{0.0f};
  float half_diagonal_ = 1.0f;
  std::vector<vec3> directions_;  // world space, towards the mirror from each camera
  std::vector<View> views_;
  gpu::Texture maps_;
  std::vector<ZexelMap2D> cpu_;  // map-major, then level
};

}  // namespace mirage
