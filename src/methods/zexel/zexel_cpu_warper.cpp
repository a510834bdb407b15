#include "methods/zexel/zexel_cpu_warper.h"

#include <algorithm>
#include <atomic>
#include <bit>

#include <tbb/parallel_for.h>

#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"
#include "methods/zexel/zexel_warp_shared.h"
#include "shading/shading.h"

namespace mirage {

namespace {

// A zexel as it lands: its cell (-1: none), what the cell keeps of it, and its distance's bits.
struct Landed {
  int cell = -1;
  uint32_t key = 0;
  uvec4 words{0u};
};

// A tile of a plan: its map, its level, its word and its first zexel's number in the warp (the
// numbers break ties between zexels at one distance in one cell the same way on every run).
struct PlannedTile {
  size_t map;
  int level;
  const ZexelTileWord* word;
  uint32_t first;
};

// zexel_warp.comp's splat(): where zexel `k` of a planned tile lands and what its cell keeps.
Landed land(const ZexelWarpSource& source, const PlannedTile& t, int k, const mat3& po_inverse,
            const WarpCamera& out, const ZexelSplatOptions& options, int margin) {
  Landed l;
  const int span = options.tile_level - t.level, n = 1 << span;
  const ivec2 texel = zexelTileOf(*t.word) * n + ivec2(k & (n - 1), k >> span);
  const ZexelMap2D& map = source.levels[t.level];
  if (texel.x >= map.width || texel.y >= map.height) return l;
  const vec4& zexel = map.texels[size_t(texel.y) * size_t(map.width) + size_t(texel.x)];
  if (!(zexel.w > 0.0f)) return l;
  const mat3 p = shading::zexel_level_matrix(source.camera.p, t.level);
  const vec2 xi = vec2(texel) + 0.5f;
  const float delta =
      zexel.w >= map.sky ? 0.0f : shading::zexel_disparity_from_distance(p, xi, zexel.w);
  const vec3 o = shading::zexel_warp(po_inverse, p, source.camera.c, out.c, delta, xi);
  if (!(o.z > 0.0f)) return l;
  const vec2 landed(o);
  const float distance =
      shading::zexel_distance_from(p, source.camera.c, xi, delta, out.c, shading::MISS_DISTANCE);
  const int side = options.splat > 0 ? options.splat
                                     : shading::zexel_splat_side(
                                           po_inverse, p, source.camera.c, out.c, delta, xi, landed,
                                           kMaxAutoSplat * options.unit, options.unit);
  const ivec2 first = shading::zexel_splat_origin(landed, side);
  const ivec4& r = options.rect;
  if (first.x >= r.z || first.y >= r.w || first.x + side <= r.x || first.y + side <= r.y) return l;
  l.cell = shading::zexel_cell_index(ivec2(glm::floor(landed)), r, margin);
  l.key = std::bit_cast<uint32_t>(distance);
  const float sigma = shading::zexel_kernel_sigma(std::bit_cast<float>(t.word->spacing_bits));
  l.words = shading::zexel_cell(l.key, landed, side, vec3(zexel), sigma);
  return l;
}

// atomicMin of a cell's (distance, number).
void keepNearest(std::atomic<uint64_t>& cell, uint64_t key) {
  uint64_t now = cell.load(std::memory_order_relaxed);
  while (key < now && !cell.compare_exchange_weak(now, key, std::memory_order_relaxed)) {
  }
}

}  // namespace

}  // namespace mirage

// The shared gather and fill read the cells through these accessors; the cells are the calling
// thread's.
namespace mirage::shading {
namespace {
thread_local const mirage::ZexelCells* g_cells = nullptr;
thread_local ivec4 g_rect{0};
thread_local int g_margin = 0;
}  // namespace
inline uvec4 zexel_cell_at(ivec2 pixel) {
  const int at = zexel_cell_index(pixel, g_rect, g_margin);
  return at < 0 ? uvec4(MIRAGE_ZEXEL_EMPTY) : (*g_cells)[size_t(at)];
}
inline uint zexel_key_at(ivec2 pixel) {
  return zexel_cell_at(pixel).x;
}
}  // namespace mirage::shading

#include "methods/zexel/zexel_fill_shared.h"
#include "methods/zexel/zexel_gather_shared.h"

namespace mirage {

namespace {

void readCells(const ZexelCells& cells, const ZexelSplatOptions& options) {
  shading::g_cells = &cells;
  shading::g_rect = options.rect;
  shading::g_margin = zexelCellMargin(options);
}

}  // namespace

vec4 gatherZexels(const ZexelCells& cells, const ZexelSplatOptions& options, ivec2 pixel) {
  readCells(cells, options);
  return shading::zexel_gather(pixel, zexelSplatReach(options), zexelSplatsAllCover(options),
                               options.tolerance);
}

vec4 fillZexel(const ZexelCells& cells, const ZexelSplatOptions& options, int fill, ivec2 pixel) {
  readCells(cells, options);
  return shading::zexel_farthest_neighbour(pixel, fill, options.unit, options.rect);
}

int zexelSplatReach(const ZexelSplatOptions& options) {
  return (options.splat > 0 ? options.splat : kMaxAutoSplat * options.unit) / 2;
}

bool zexelSplatsAllCover(const ZexelSplatOptions& options) {
  return options.splat > 0 && options.splat % 2 == 1;
}

int zexelCellMargin(const ZexelSplatOptions& options) {
  return std::max(zexelSplatReach(options), options.unit);
}

size_t zexelCellCount(const ZexelSplatOptions& options) {
  const int margin = zexelCellMargin(options);
  return size_t(options.rect.z - options.rect.x + 2 * margin) *
         size_t(options.rect.w - options.rect.y + 2 * margin);
}

ZexelCells warpZexels(const std::vector<ZexelWarpSource>& sources,
                      const std::vector<ZexelTilePlan>& plans, const WarpCamera& out,
                      const ZexelSplatOptions& options, bool parallel) {
  const int margin = zexelCellMargin(options);
  const size_t count = zexelCellCount(options);
  std::vector<std::atomic<uint64_t>> nearest(count);
  for (auto& n : nearest) n.store(~uint64_t(0), std::memory_order_relaxed);
  const mat3 po_inverse = glm::inverse(out.p);
  std::vector<PlannedTile> tiles;
  uint32_t zexels = 0;
  for (size_t m = 0; m < sources.size(); ++m)
    for (size_t l = 0; l < plans[m].by_level.size(); ++l) {
      const int level = plans[m].finest + int(l), span = plans[m].tile_level - level;
      for (const ZexelTileWord& w : plans[m].by_level[l]) {
        tiles.push_back({m, level, &w, zexels});
        zexels += 1u << (2 * span);
      }
    }
  // Every zexel of every tile, in parallel over the tiles.
  auto forEachZexel = [&](auto&& body) {
    auto tile = [&](size_t i) {
      const PlannedTile& t = tiles[i];
      const int per = 1 << (2 * (options.tile_level - t.level));
      for (int k = 0; k < per; ++k) {
        const Landed l = land(sources[t.map], t, k, po_inverse, out, options, margin);
        if (l.cell >= 0) body(l, (uint64_t(l.key) << 32) | (t.first + uint32_t(k)));
      }
    };
    if (parallel)
      tbb::parallel_for(size_t(0), tiles.size(), tile);
    else
      for (size_t i = 0; i < tiles.size(); ++i) tile(i);
  };
  // Pass 0: each cell's nearest (distance, number); pass 1: that zexel's words.
  forEachZexel([&](const Landed& l, uint64_t key) { keepNearest(nearest[size_t(l.cell)], key); });
  ZexelCells cells(count, uvec4(MIRAGE_ZEXEL_EMPTY, 0u, 0u, 0u));
  forEachZexel([&](const Landed& l, uint64_t key) {
    if (nearest[size_t(l.cell)].load(std::memory_order_relaxed) == key)
      cells[size_t(l.cell)] = l.words;
  });
  return cells;
}

ZexelCells warpZexels(const std::vector<ZexelWarpSource>& sources, const WarpCamera& out,
                      const ZexelSplatOptions& options, bool parallel) {
  std::vector<ZexelTilePlan> plans;
  for (const ZexelWarpSource& s : sources) plans.push_back(planZexelTiles(s, out, options));
  return warpZexels(sources, plans, out, options, parallel);
}

std::vector<ZexelMap2D> zexelPyramid(const ZexelMap2D& level0) {
  std::vector<ZexelMap2D> levels = {level0};
  while (levels.back().width > 1) {
    const ZexelMap2D& fine = levels.back();
    ZexelMap2D coarse;
    coarse.width = coarse.height = std::max(fine.width / 2, 1);
    coarse.sky = fine.sky;
    coarse.texels.resize(size_t(coarse.width) * size_t(coarse.height));
    auto child = [&](int x, int y) {
      return fine.texels[size_t(y) * size_t(fine.width) + size_t(x)];
    };
    for (int y = 0; y < coarse.height; ++y)
      for (int x = 0; x < coarse.width; ++x)
        coarse.texels[size_t(y) * size_t(coarse.width) + size_t(x)] =
            shading::zexel_parent(child(2 * x, 2 * y), child(2 * x + 1, 2 * y),
                                  child(2 * x, 2 * y + 1), child(2 * x + 1, 2 * y + 1));
    levels.push_back(std::move(coarse));
  }
  return levels;
}

}  // namespace mirage
