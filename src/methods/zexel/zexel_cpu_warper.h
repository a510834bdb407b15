// The CPU warper of the zexel method: the GPU warper's algorithm (zexel_warp.comp) in C++ on the
// same shared code (zexel_warp_shared.h, zexel_splat_shared.h) — the planned tiles at their
// levels, McMillan's warp, each zexel into the cell of the pixel it lands in — with the tiles on
// parallel threads (TBB). A cell keeps the least (distance, zexel number): a minimum, so the
// cells are the same to the bit whatever the threads and their interleaving.
//
// The paper (§4.1) resolves zexels landing on one pixel by McMillan's occlusion-compatible order
// instead of a z-buffer, in parallel over the sheets about the epipole. A blend over a depth
// tolerance needs each pixel's front distance before it can blend, which that order gives only
// after the last write; and where splats of two parallel sheets (or wedges) met, which zexel was
// written last depended on the threads' timing. So both warpers take the nearest distance.
#pragma once

#include <cstdint>
#include <vector>

#include "methods/zexel/zexel_tiles.h"
#include "methods/zexel/zexel_warp_types.h"

namespace mirage {

// The warp's cells: per pixel of the mirror's rectangle (options.rect, within the image) and a
// margin of zexelCellMargin pixels around it, rows from the bottom (zexel_cell_index), the
// nearest zexel that landed there (zexel_cell; x MIRAGE_ZEXEL_EMPTY where none did) — the words
// the GPU warper leaves.
using ZexelCells = std::vector<uvec4>;

// How far a splat reaches from the pixel it landed in (the largest side / 2); the cells kept
// around the mirror's rectangle (that, and at least an output pixel: the fill looks there); and
// how many cells.
int zexelSplatReach(const ZexelSplatOptions& options);
// Whether every splat is 2 reach + 1 wide (a fixed odd side): each within the reach covers.
bool zexelSplatsAllCover(const ZexelSplatOptions& options);
int zexelCellMargin(const ZexelSplatOptions& options);
size_t zexelCellCount(const ZexelSplatOptions& options);

// Warps `sources` (one or two maps, with their tile plans) into the cells of the image seen by
// `out`, the tiles on parallel threads when `parallel` (in the calling task arena). Ties (one
// distance, one cell) go to the zexel first in the plans, whatever the threads.
ZexelCells warpZexels(const std::vector<ZexelWarpSource>& sources,
                      const std::vector<ZexelTilePlan>& plans, const WarpCamera& out,
                      const ZexelSplatOptions& options, bool parallel);
// The same, planning the tiles first (planZexelTiles).
ZexelCells warpZexels(const std::vector<ZexelWarpSource>& sources, const WarpCamera& out,
                      const ZexelSplatOptions& options, bool parallel);

// What the mirror shows at `pixel` of those cells (zexel_gather_shared.h, as zexel_resolve.comp
// runs it): rgb and the nearest covering splat's distance; alpha -1 where none covers it.
vec4 gatherZexels(const ZexelCells& cells, const ZexelSplatOptions& options, ivec2 pixel);
// What the fill (zexel_fill_shared.h) finds for exposed pixel `pixel` within `fill` output pixels
// (alpha -1: nothing).
vec4 fillZexel(const ZexelCells& cells, const ZexelSplatOptions& options, int fill, ivec2 pixel);

// A map's coarser levels from its level 0 as zexel_pyramid.comp builds them (zexel_parent): the
// levels of a map the tests and benchmarks make on the CPU.
std::vector<ZexelMap2D> zexelPyramid(const ZexelMap2D& level0);

}  // namespace mirage
