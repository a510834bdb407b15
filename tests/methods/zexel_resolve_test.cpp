// The zexel mirror's resolve on the GPU (zexel_resolve.comp: a sliding window of cells where
// splats reach a pixel, the gather's loop elsewhere) and its fill (zexel_fill.comp, from the
// exposures the resolve lists) against the same shared code on the CPU (gatherZexels,
// fillZexel), on random cells: every pixel of the mirror's rectangle shows the same splats' blend
// and distance, the same pixels are exposures, and the fill finds the same zexels for them.
#include <gtest/gtest.h>

#include <bit>
#include <random>

#include "methods/zexel/zexel_cpu_warper.h"
#include "methods/zexel/zexel_resolve_pass.h"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

// Cells of `o` filled at random: a share `empty` of them empty; distances near one another (so that
// the depth tolerance decides) or far; landings anywhere in their pixel; sides `o.splat` (or 1
// to 8 for magnification-sized splats); kernels from sharp to wide.
ZexelCells randomCells(const ZexelSplatOptions& o, float empty, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const int margin = zexelCellMargin(o);
  ZexelCells cells(zexelCellCount(o), uvec4(MIRAGE_ZEXEL_EMPTY, 0u, 0u, 0u));
  for (int y = o.rect.y - margin; y < o.rect.w + margin; ++y)
    for (int x = o.rect.x - margin; x < o.rect.z + margin; ++x) {
      if (unit(rng) < empty) continue;
      const float distance = unit(rng) < 0.7f ? 2.0f + 0.06f * unit(rng) : 2.0f + 3.0f * unit(rng);
      const int side = o.splat > 0 ? o.splat : 1 + int(unit(rng) * 7.99f);
      const vec3 color(unit(rng), unit(rng), unit(rng));
      const int at = shading::zexel_cell_index({x, y}, o.rect, margin);
      cells[size_t(at)] = shading::zexel_cell(std::bit_cast<uint32_t>(distance),
                                              vec2(x, y) + vec2(unit(rng), unit(rng)), side, color,
                                              0.3f + 1.2f * unit(rng));
    }
  return cells;
}

class ZexelResolve : public GlTest {};

TEST_F(ZexelResolve, GpuResolveAndFillEqualTheSharedCodeOnTheCpu) {
  // Splat sides: 3 (the default: the window, every splat covering), 2 (the window, coverage
  // tested), 1, 5 and magnification-sized (the loop, reaching 0, 2 and 4 pixels); the fill within
  // 6 pixels, none, and 2 x 2 sub-pixels a pixel (--ssaa 2: splats and walk in output pixels);
  // one in five cells empty, and nine in ten (where the fill finds nothing for some exposures).
  struct Case {
    int splat, unit, fill;
    float empty;
  };
  for (const Case c :
       {Case{3, 1, 6, 0.2f}, Case{2, 1, 6, 0.2f}, Case{1, 1, 6, 0.2f}, Case{1, 1, 0, 0.2f},
        Case{1, 1, 2, 0.9f}, Case{5, 1, 6, 0.2f}, Case{0, 1, 6, 0.2f}, Case{2, 2, 3, 0.2f}}) {
    const int splat = c.splat;
    ZexelSplatOptions o;
    o.splat = splat;
    o.unit = c.unit;
    o.rect = ivec4(37, 21, 37 + 93, 21 + 70);  // not a multiple of the strips or groups
    o.tolerance = 0.02f;
    const ZexelCells cells = randomCells(o, c.empty, 17u + uint32_t(splat));
    ZexelWarpTarget target;
    target.resize({200, 120}, o, false);
    std::vector<uint32_t> keys(cells.size());
    for (size_t i = 0; i < keys.size(); ++i) keys[i] = cells[i].x;
    target.keys().upload(std::span<const uint32_t>(keys));
    target.cells().upload(std::span<const uvec4>(cells));
    ZexelResolvePass(o).run(o, c.fill, target);
    const int width = o.rect.z - o.rect.x, height = o.rect.w - o.rect.y;
    std::vector<vec4> resolved(size_t(width) * size_t(height));
    target.resolved().download(resolved.data(), resolved.size() * sizeof(vec4));
    uint32_t listed[MIRAGE_ZEXEL_EXPOSURES_HEADER];
    target.exposures().download(listed, sizeof(listed));
    size_t exposures = 0, filled = 0, differing = 0;
    float largest = 0.0f;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const ivec2 pixel(o.rect.x + x, o.rect.y + y);
        vec4 cpu = gatherZexels(cells, o, pixel);
        if (cpu.w < 0.0f) {
          ++exposures;
          // The resolve's marker, or the negated distance of what the fill found.
          const vec4 found = c.fill > 0 ? fillZexel(cells, o, c.fill, pixel) : vec4(-1.0f);
          filled += found.w >= 0.0f ? 1 : 0;
          cpu = found.w >= 0.0f ? vec4(vec3(found), -found.w)
                                : vec4(vec3(cpu), shading::ZEXEL_UNFILLED);
        }
        const vec4 gpu = resolved[size_t(y) * size_t(width) + size_t(x)];
        // The distance is one of the cells' (exact); the colour a ratio of weights, whose
        // exponentials llvmpipe and the C library round differently.
        const float d = glm::length(vec3(gpu) - vec3(cpu));
        largest = std::max(largest, d);
        if (gpu.w != cpu.w || d > 1e-4f) {
          if (++differing <= 5)
            ADD_FAILURE() << "splat " << splat << ", pixel " << pixel.x << "," << pixel.y
                          << ": gpu (" << gpu.x << " " << gpu.y << " " << gpu.z << " " << gpu.w
                          << "), cpu (" << cpu.x << " " << cpu.y << " " << cpu.z << " " << cpu.w
                          << ")";
        }
      }
    std::printf(
        "splat %d, unit %d, fill %d: %zu exposures (%zu filled) of %d pixels, %zu "
        "differ, largest colour difference %g\n",
        splat, c.unit, c.fill, exposures, filled, width * height, differing, double(largest));
    EXPECT_EQ(differing, 0u) << "splat " << splat;
    // The list holds every exposure, and the fill's dispatch a group per 64 of them.
    const uint32_t listed_count = c.fill > 0 ? uint32_t(exposures) : 0u;
    EXPECT_EQ(listed[3], listed_count);
    EXPECT_EQ(listed[0], (listed_count + MIRAGE_ZEXEL_FILL_GROUP - 1) / MIRAGE_ZEXEL_FILL_GROUP);
    // Random cells leave some pixels uncovered where splats are small (and the fill finds
    // zexels for most of them), none where they are not.
    if (splat == 1) {
      EXPECT_GT(exposures, 100u);
      if (c.fill > 0) {
        EXPECT_GT(filled, exposures / 2);
      }
    }
  }
}

}  // namespace
}  // namespace mirage::test
