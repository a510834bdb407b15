// The per-frame warp of a mirror's chosen maps into the image seen from the mirrored eye, by the
// GPU warper (zexel_warp.comp) or the CPU one (zexel_cpu_warper.h), into the same cells the
// mirror's shader gathers from (zexel_shared.h, zexel_splat_shared.h).
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/zexel/zexel_maps.h"
#include "methods/zexel/zexel_tiles.h"

namespace mirage {

// What one mirror's warp needs: the maps, the ones chosen (one or two: slots 0 and 1), how their
// tiles and splats go (ZexelSplatOptions: the tiles' level and the finest they may warp, splats,
// the mirror's pixels, the spacing goal, the depth tolerance), and each chosen map's tile plan.
struct ZexelWarpJob {
  const ZexelMirrorMaps* maps = nullptr;
  std::vector<int> chosen;
  ZexelSplatOptions splats;
  std::vector<ZexelTilePlan> plans;
};

// Plans the tiles of the job's chosen maps for `output` (zexel_tiles.h).
void planZexelJob(ZexelWarpJob& job, const View& output);

// A mirror's cells (zexelCellCount: their keys apart, the rest), the tiles of its warp, what its
// rectangle's pixels show (the resolve's texels), and its last image (the no-clear option,
// frame-sized).
class ZexelWarpTarget {
 public:
  void resize(ivec2 size, const ZexelSplatOptions& splats, bool history);
  ivec2 size() const { return size_; }
  // The first `cells` cells empty (their keys).
  void clear(size_t cells) const;
  void bind() const;  // the buffers at their bindings and the history image (the warp)
  // The keys, cells and resolved texels as buffer textures at their units and the history image
  // (the mirror).
  void bindTexels() const;
  // The resolve's output, one texel a pixel of the mirror's rectangle `rect` (zexel_resolve.comp;
  // rows from the rectangle's lowest): made to hold it, as the image the resolve writes, and as
  // a buffer.
  void reserveResolved(const ivec4& rect);
  void bindResolvedImage() const;
  const gpu::Buffer& resolved() const { return resolved_; }
  gpu::Buffer& keys() { return keys_; }
  gpu::Buffer& cells() { return cells_; }
  // The tiles' words of a plan, uploaded.
  gpu::Buffer& tiles() { return tiles_; }

 private:
  ivec2 size_{0};
  size_t cells_count_ = 0, resolved_count_ = 0;
  gpu::Buffer keys_, cells_, tiles_, resolved_;
  gpu::Texture keys_texels_, cells_texels_, resolved_texels_, history_;
};

// The GPU warper: per pass (nearest distances, then the cells) and chosen map, one dispatch of an
// invocation per zexel of every level of its plan.
void warpOnGpu(const gpu::Program& program, const ZexelWarpJob& job, const View& output,
               ZexelWarpTarget& target);

// The CPU warper on up to `threads` threads (0: all), uploaded into the same cells.
void warpOnCpu(const ZexelWarpJob& job, const View& output, int threads, ZexelWarpTarget& target);

}  // namespace mirage
