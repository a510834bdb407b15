// The zexel mirror's resolve on the GPU (zexel_resolve.comp: a sliding window of cells where
// splats reach a pixel, the gather's loop elsewhere) against the same shared code on the CPU
// (gatherZexels), on random cells: every pixel of the mirror's rectangle shows the same splats'
// blend and distance, and the same pixels are exposures. And the fill (zexel_fill_shared.h, as
// the mirror's shader runs it) on cells laid out by hand.
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

TEST_F(ZexelResolve, GpuResolveEqualsTheGatherOnTheCpu) {
  // Splat sides: 3 (the default: the window, every splat covering), 2 (the window, coverage
  // tested), 1, 5 and magnification-sized (the loop, reaching 0, 2 and 4 pixels), and 2 x 2
  // sub-pixels a pixel (--ssaa 2); one in five cells empty, and nine in ten.
  struct Case {
    int splat, unit;
    float empty;
  };
  for (const Case c : {Case{3, 1, 0.2f}, Case{2, 1, 0.2f}, Case{1, 1, 0.2f}, Case{1, 1, 0.9f},
                       Case{5, 1, 0.2f}, Case{0, 1, 0.2f}, Case{2, 2, 0.2f}}) {
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
    ZexelResolvePass(o).run(o, target);
    const int width = o.rect.z - o.rect.x, height = o.rect.w - o.rect.y;
    std::vector<vec4> resolved(size_t(width) * size_t(height));
    target.resolved().download(resolved.data(), resolved.size() * sizeof(vec4));
    size_t exposures = 0, differing = 0;
    float largest = 0.0f;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const ivec2 pixel(o.rect.x + x, o.rect.y + y);
        const vec4 cpu = gatherZexels(cells, o, pixel);
        exposures += cpu.w < 0.0f ? 1 : 0;
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
        "splat %d, unit %d, empty %.1f: %zu exposures of %d pixels, %zu differ, largest "
        "colour difference %g\n",
        splat, c.unit, double(c.empty), exposures, width * height, differing, double(largest));
    EXPECT_EQ(differing, 0u) << "splat " << splat;
    // Random cells leave some pixels uncovered where splats are small.
    if (splat == 1) {
      EXPECT_GT(exposures, 100u);
    }
  }
}

// The fill walks from an exposed pixel in eight directions and takes the farthest of the first
// zexels met: here a near zexel two pixels to the right, a far one three pixels up, and a farther
// one beyond the near one (which the walk to the right never reaches); within a radius of 2 only
// the near one is met; alone in an empty rectangle nothing is.
TEST(ZexelFill, TakesTheFarthestOfTheFirstZexelsMetInEightDirections) {
  ZexelSplatOptions o;
  o.rect = ivec4(0, 0, 16, 16);
  const int margin = zexelCellMargin(o);
  ZexelCells cells(zexelCellCount(o), uvec4(MIRAGE_ZEXEL_EMPTY, 0u, 0u, 0u));
  auto put = [&](ivec2 at, float distance, vec3 color) {
    cells[size_t(shading::zexel_cell_index(at, o.rect, margin))] =
        shading::zexel_cell(std::bit_cast<uint32_t>(distance), vec2(at) + 0.5f, 3, color, 0.5f);
  };
  const ivec2 pixel(8, 8);
  const vec3 red(1.0f, 0.0f, 0.0f), green(0.0f, 1.0f, 0.0f), blue(0.0f, 0.0f, 1.0f);
  EXPECT_LT(fillZexel(cells, o, 16, pixel).w, 0.0f);
  put({10, 8}, 2.0f, red);    // right, near
  put({13, 8}, 9.0f, blue);   // right, behind the near one
  put({8, 11}, 5.0f, green);  // up, far
  EXPECT_EQ(fillZexel(cells, o, 16, pixel), vec4(green, 5.0f));
  EXPECT_EQ(fillZexel(cells, o, 2, pixel), vec4(red, 2.0f));
  EXPECT_LT(fillZexel(cells, o, 1, pixel).w, 0.0f);
}

}  // namespace
}  // namespace mirage::test
