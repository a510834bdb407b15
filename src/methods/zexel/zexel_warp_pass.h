// The per-frame warp of a mirror's chosen maps into the image seen from the mirrored eye, by the
// GPU warper (zexel_warp.comp) or the CPU one (zexel_cpu_warper.h), into the same per-pixel words
// the mirror's shader reads (zexel_shared.h): the nearest landed distance and the zexel shown.
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "methods/zexel/zexel_maps.h"

namespace mirage {

// What one mirror's warp needs: the maps, the ones chosen (one or two: slots 0 and 1), the level.
struct ZexelWarpJob {
  const ZexelMirrorMaps* maps = nullptr;
  std::vector<int> chosen;
  int level = 0;
  int splat = 3;        // 0: from the warp's magnification
  ivec4 rect{0};        // the mirror's pixels (window coordinates) lie in [xy, zw)
  int pixel_scale = 1;  // frame pixels per output pixel along a side (--ssaa)
};

// A mirror's per-pixel words, frame-sized, and its last image (the no-clear option).
class ZexelWarpTarget {
 public:
  void resize(ivec2 size, bool history);
  ivec2 size() const { return size_; }
  // Both words of every pixel to MIRAGE_ZEXEL_EMPTY.
  void clear() const;
  void bind() const;  // the buffers at their bindings and the history image
  gpu::Buffer& keys() { return keys_; }
  gpu::Buffer& indices() { return indices_; }

 private:
  ivec2 size_{0};
  gpu::Buffer keys_, indices_;
  gpu::Texture history_;
};

// The GPU warper: two dispatches per chosen map (nearest distances, then indices).
void warpOnGpu(const gpu::Program& program, const ZexelWarpJob& job, const View& output,
               ZexelWarpTarget& target);

// The CPU warper: each chosen map in McMillan's occlusion-compatible order (the sheets on up to
// `threads` threads; 0: all), the two maps merged by distance, uploaded. Returns the zexels
// warped.
long warpOnCpu(const ZexelWarpJob& job, const View& output, int threads, ZexelWarpTarget& target);

}  // namespace mirage
