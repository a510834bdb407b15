// The zexel warp's tiles (zexel_splat_shared.h): which tiles of a map can reach the mirror's
// pixels, the level each warps and its surface's spacing there. Planned once per frame and map on
// the CPU from the map's tile level (kept on the CPU: a few thousand zexels) and shared by both
// warpers: the GPU warper then runs one invocation per zexel, each dispatch one level, and the CPU
// warper walks the same tiles.
#pragma once

#include <cstdint>
#include <vector>

#include "methods/zexel/zexel_warp_types.h"

namespace mirage {

// A tile to warp: its coordinates packed (x | y << 16) and its surface's spacing in pixels at its
// level (a float's bits): the GPU words of MIRAGE_BIND_ZEXEL_TILES.
struct ZexelTileWord {
  uint32_t tile = 0, spacing_bits = 0;
};

struct ZexelTilePlan {
  int tile_level = 0, finest = 0;
  // The tiles warping each level, finest first: by_level[l - finest].
  std::vector<std::vector<ZexelTileWord>> by_level;
  long zexels = 0, tiles = 0, level_sum = 0;  // what the tiles warp, for the method's stats
};

// Plans map `source` (its levels down to at least options.tile_level; only that level is read)
// seen by `out` into an image `size` pixels (options.rect: the mirror's pixels).
ZexelTilePlan planZexelTiles(const ZexelWarpSource& source, const WarpCamera& out,
                             const ZexelSplatOptions& options);

// The tile of a word and its spacing.
inline ivec2 zexelTileOf(const ZexelTileWord& w) {
  return ivec2(int(w.tile & 0xffffu), int(w.tile >> 16));
}

}  // namespace mirage
