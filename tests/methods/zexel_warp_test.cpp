// The zexel method's warp on the CPU, on the code the shaders share: the planned, culled warp
// leaves in each cell what a brute-force warp of the full map does; the CPU warper's cells do not
// depend on its threads; the gather blends the front surface's splats by their kernels and
// keeps a farther one out; a tile's level keeps its warped surface within the splats' reach.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "methods/zexel/zexel_camera.h"
#include "methods/zexel/zexel_cpu_warper.h"
#include "methods/zexel/zexel_splat_shared.h"
#include "methods/zexel/zexel_warp_shared.h"

namespace mirage::test {
namespace {

using shading::zexel_disparity_from_distance;
using shading::zexel_warp;

// A map ray-cast on the CPU: three spheres at different depths in front of the mirror and a
// wall behind them, seen from the reference camera.
ZexelMap2D analyticMap(const View& reference, int size) {
  const mat3 p = zexelPixelMatrix(reference, reference.nearPlane());
  const vec4 spheres[3] = {
      {0.0f, 1.0f, -1.2f, 0.35f}, {0.4f, 1.2f, -0.6f, 0.2f}, {-0.5f, 0.8f, 0.0f, 0.25f}};
  ZexelMap2D map;
  map.width = map.height = size;
  map.texels.resize(size_t(size) * size_t(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const vec3 d = glm::normalize(p * vec3(float(x) + 0.5f, float(y) + 0.5f, 1.0f));
      const vec3 o = reference.eye();
      float best = (2.0f - o.z) / d.z;  // the wall z = 2
      vec3 color(0.5f);
      for (const vec4& s : spheres) {
        const vec3 oc = o - vec3(s);
        const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.w * s.w, disc = b * b - c;
        if (disc < 0.0f) continue;
        const float t = -b - std::sqrt(disc);
        if (t > 0.0f && t < best) {
          best = t;
          color = vec3(s.w);
        }
      }
      map.texels[size_t(y) * size_t(size) + size_t(x)] = vec4(color, best > 0.0f ? best : 0.0f);
    }
  return map;
}

// Where a zexel of `map` lands in `out` and its distance from the output camera (w <= 0: none).
vec4 landingOf(const ZexelMap2D& map, const WarpCamera& in, const WarpCamera& out, ivec2 texel) {
  const vec4& t = map.texels[size_t(texel.y) * size_t(map.width) + size_t(texel.x)];
  if (!(t.w > 0.0f)) return vec4(0.0f, 0.0f, -1.0f, 0.0f);
  const vec2 xi = vec2(texel) + 0.5f;
  const float delta = zexel_disparity_from_distance(in.p, xi, t.w);
  const vec3 o = zexel_warp(glm::inverse(out.p), in.p, in.c, out.c, delta, xi);
  return vec4(o, glm::length(in.c + glm::normalize(in.p * vec3(xi, 1.0f)) * t.w - out.c));
}

// The analytic scene of the warper tests: its map (colours varying per zexel, so that a pixel
// showing another zexel shows), the map's levels and the two mirrored eyes (far from the mirror:
// a negative epipole; close: positive).
struct WarpScene {
  View reference;
  ZexelMap2D map;
  std::vector<ZexelMap2D> levels;
  WarpCamera in;
  std::vector<View> outputs;
};

WarpScene warpScene(int size, ivec2 output) {
  const vec3 mirror(0.0f, 1.0f, -2.0f), normal(0.0f, 0.0f, 1.0f);
  WarpScene w;
  w.reference = zexelReferenceView(mirror, normal, 1.2f, size, 100.0f);
  w.map = analyticMap(w.reference, size);
  for (size_t i = 0; i < w.map.texels.size(); ++i)
    w.map.texels[i] =
        vec4(vec3(w.map.texels[i]) * (0.5f + 0.5f * float(i % 97) / 97.0f), w.map.texels[i].w);
  w.levels = zexelPyramid(w.map);
  w.in = {zexelPixelMatrix(w.reference, w.reference.nearPlane()), w.reference.eye()};
  for (vec3 eye_position : {vec3(1.2f, 1.5f, 3.0f), vec3(0.3f, 1.1f, -1.5f)}) {
    CameraDesc eye;
    eye.position = eye_position;
    eye.target = mirror;
    w.outputs.push_back(View(eye, output).mirrored(mirror, normal));
  }
  return w;
}

WarpCamera cameraOf(const View& v) {
  return {zexelPixelMatrix(v, v.nearPlane()), v.eye()};
}

// The warp's tiles are culled where they cannot reach the mirror's pixels, conservatively: the
// cells equal a brute-force warp of every zexel of the full map (the hierarchy off).
TEST(ZexelCpuWarper, CellsHoldTheNearestZexelLandingThere) {
  const WarpScene w = warpScene(200, {240, 180});
  for (const View& output : w.outputs) {
    const WarpCamera out = cameraOf(output);
    ZexelSplatOptions o;
    o.rect = ivec4(30, 20, 200, 150);  // a mirror's pixels, within the image
    o.tile_level = 3;
    o.lod = false;
    const ZexelCells cells =
        warpZexels({{w.levels.data(), int(w.levels.size()), 200, w.in}}, out, o, false);
    // By brute force: each cell's nearest landed distance.
    const int margin = zexelCellMargin(o);
    std::vector<float> nearest(cells.size(), std::numeric_limits<float>::infinity());
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 200; ++x) {
        const vec4 l = landingOf(w.map, w.in, out, {x, y});
        if (!(l.z > 0.0f)) continue;
        const ivec2 first = shading::zexel_splat_origin(vec2(l), o.splat);
        if (first.x >= o.rect.z || first.y >= o.rect.w || first.x + o.splat <= o.rect.x ||
            first.y + o.splat <= o.rect.y)
          continue;
        const int at = shading::zexel_cell_index(ivec2(glm::floor(vec2(l))), o.rect, margin);
        if (at >= 0) nearest[size_t(at)] = std::min(nearest[size_t(at)], l.w);
      }
    size_t filled = 0;
    for (size_t i = 0; i < nearest.size(); ++i) {
      const uint32_t key = cells[i].x;
      if (std::isinf(nearest[i])) {
        EXPECT_EQ(key, kNoZexel) << i;
        continue;
      }
      ++filled;
      ASSERT_NE(key, kNoZexel) << i;
      EXPECT_NEAR(std::bit_cast<float>(key), nearest[i], 1e-4f * nearest[i]) << i;
    }
    std::printf("%zu of %zu cells hold a zexel\n", filled, nearest.size());
    EXPECT_GT(filled, nearest.size() / 10);
  }
}

// The CPU warper's threads share the cells; whatever their number and interleaving the cells
// are the same to the bit (each keeps the least distance and zexel number). The paper's
// occlusion-compatible order, which this warper ran before, wrote 1012 of these pixels
// differently on 1 and 2 threads (last writer wins where splats of two wedges met).
TEST(ZexelCpuWarper, CellsDoNotDependOnTheThreads) {
  const WarpScene w = warpScene(512, {640, 480});
  for (const View& output : w.outputs)
    for (bool lod : {false, true}) {
      ZexelSplatOptions o;
      o.rect = ivec4(0, 0, 640, 480);
      o.tile_level = 3;
      o.lod = lod;
      const std::vector<ZexelWarpSource> sources = {
          {w.levels.data(), int(w.levels.size()), 512, w.in}};
      auto warp = [&](int threads) {
        tbb::task_arena arena(threads);
        ZexelCells cells;
        arena.execute([&] { cells = warpZexels(sources, cameraOf(output), o, threads > 1); });
        return cells;
      };
      const ZexelCells one = warp(1);
      size_t filled = 0;
      for (const uvec4& c : one) filled += c.x != kNoZexel ? 1 : 0;
      EXPECT_GT(filled, one.size() / 10);
      for (int threads : {2, 4, 2}) {
        const ZexelCells many = warp(threads);
        ASSERT_EQ(many.size(), one.size());
        EXPECT_EQ(std::memcmp(many.data(), one.data(), one.size() * sizeof(uvec4)), 0)
            << threads << " threads, hierarchy " << lod;
      }
    }
}

// The blend, on the gather the mirror's shader runs: splats within the depth tolerance of the
// nearest are averaged by their kernels' weights at the pixel's centre; a farther one is out;
// one nearer than the tolerance takes the pixel alone.
TEST(ZexelBlend, FrontSurfaceSplatsBlendByWeightAndFartherOnesStayOut) {
  ZexelSplatOptions o;
  o.rect = ivec4(0, 0, 9, 9);
  o.tolerance = 0.02f;
  const int margin = zexelCellMargin(o);  // 3x3 splats reach a pixel
  const ivec2 pixel(4, 4);
  const vec2 centre = vec2(pixel) + 0.5f;
  const float sigma = 0.8f, falloff = 0.5f / (sigma * sigma);
  auto put = [&](ZexelCells& cells, ivec2 at, vec2 offset, float distance, vec3 color) {
    cells[size_t(shading::zexel_cell_index(at, o.rect, margin))] =
        shading::zexel_cell(std::bit_cast<uint32_t>(distance), vec2(at) + offset, 3, color, sigma);
  };
  auto empty = [&] { return ZexelCells(zexelCellCount(o), uvec4(kNoZexel, 0u, 0u, 0u)); };
  const vec3 red(1.0f, 0.0f, 0.0f), green(0.0f, 1.0f, 0.0f), blue(0.0f, 0.0f, 1.0f);
  const float near = 2.0f, within = near * 1.015f, beyond = near * 1.5f;
  // Two surfaces within the tolerance, one landed 0.3 px from the pixel's centre and one 0.9 px
  // away, and a farther one landed on the centre's neighbour: every splat covers the pixel.
  ZexelCells cells = empty();
  put(cells, {4, 4}, {0.8f, 0.5f}, within, green);  // 0.3 px right of the centre
  put(cells, {3, 4}, {0.6f, 0.5f}, near, red);      // 0.9 px left
  put(cells, {4, 5}, {0.5f, 0.3f}, beyond, blue);   // 0.8 px up, behind both
  const float w_green = shading::zexel_weight(centre, vec2(4.8f, 4.5f), falloff);
  const float w_red = shading::zexel_weight(centre, vec2(3.6f, 4.5f), falloff);
  const vec4 blended = gatherZexels(cells, o, pixel);
  std::printf("blend: (%.4f %.4f %.4f) at %.3f; weights green %.1f, red %.1f\n", blended.x,
              blended.y, blended.z, blended.w, w_green, w_red);
  // Both are strong at the pixel (the kernel within about 1.5 sigma of where they landed).
  ASSERT_GE(w_red, shading::ZEXEL_WEIGHT_STRONG);
  EXPECT_GT(w_green, 1.5f * w_red);  // the nearer landing weighs more
  EXPECT_NEAR(blended.x, w_red / (w_red + w_green), 1e-4f);
  EXPECT_NEAR(blended.y, w_green / (w_red + w_green), 1e-4f);
  EXPECT_EQ(blended.z, 0.0f);  // the farther surface stays out
  EXPECT_EQ(blended.w, near);  // the pixel's distance: the nearest
  // The tolerance 0: the nearest alone (the paper's resolution).
  o.tolerance = 0.0f;
  EXPECT_EQ(vec3(gatherZexels(cells, o, pixel)), red);
  o.tolerance = 0.02f;
  // A nearer surface whose splat only grazes the pixel (landed 1.4 px away: weak there) does not
  // hide the strong ones: no fattening by the splat's rim.
  ZexelCells grazed = cells;
  put(grazed, {5, 3}, {0.5f, 0.5f}, 1.5f, blue);
  EXPECT_LT(shading::zexel_weight(centre, vec2(5.5f, 3.5f), falloff), shading::ZEXEL_WEIGHT_STRONG);
  EXPECT_EQ(gatherZexels(grazed, o, pixel), blended);
  // At tolerance 0 the nearest splat covering the pixel takes it, weak or not (the paper's).
  o.tolerance = 0.0f;
  EXPECT_EQ(gatherZexels(grazed, o, pixel), vec4(blue, 1.5f));
  o.tolerance = 0.02f;
  // Landed near the pixel's centre, a nearer surface takes the pixel alone.
  put(cells, {4, 4}, {0.5f, 0.6f}, 1.5f, blue);
  EXPECT_EQ(gatherZexels(cells, o, pixel), vec4(blue, 1.5f));
  // Pixels no splat covers are exposures: the cells two pixels away do not reach.
  EXPECT_LT(gatherZexels(cells, o, {8, 0}).w, 0.0f);
}

// How far behind the final front a splat of the blend may be: joins chain through the front,
// which only moves nearer, so a splat met first stays in while each later one is within the
// tolerance of the one before. Four strong splats met in the pass's order, each 2 % nearer than
// the last: the first, 6.1 % behind the final front (more than twice the tolerance), is in the
// blend; on random splats no member lies more than (1 + tolerance)^(n - 1) behind, n the splats
// covering the pixel.
TEST(ZexelBlend, JoinsChainUpToTheToleranceToThePowerOfTheSplatsLess1) {
  ZexelSplatOptions o;
  o.rect = ivec4(0, 0, 9, 9);
  o.tolerance = 0.02f;
  const int margin = zexelCellMargin(o);
  const ivec2 pixel(4, 4);
  const float sigma = 0.8f;
  auto empty = [&] { return ZexelCells(zexelCellCount(o), uvec4(kNoZexel, 0u, 0u, 0u)); };
  auto put = [&](ZexelCells& cells, ivec2 at, vec2 landed, float distance, vec3 color) {
    cells[size_t(shading::zexel_cell_index(at, o.rect, margin))] =
        shading::zexel_cell(std::bit_cast<uint32_t>(distance), landed, 3, color, sigma);
  };
  const vec3 red(1.0f, 0.0f, 0.0f), green(0.0f, 1.0f, 0.0f);
  ZexelCells chain = empty();
  // Row by row: (3, 3), (4, 3), (5, 3), then (3, 4); each landed at its corner nearest the centre.
  put(chain, {3, 3}, {3.99f, 3.99f}, 2.0f * std::pow(1.02f, 3.0f), red);
  put(chain, {4, 3}, {4.5f, 3.99f}, 2.0f * std::pow(1.02f, 2.0f), green);
  put(chain, {5, 3}, {5.01f, 3.99f}, 2.0f * 1.02f, green);
  put(chain, {3, 4}, {3.99f, 4.5f}, 2.0f, green);
  const vec4 shown = gatherZexels(chain, o, pixel);
  EXPECT_EQ(shown.w, 2.0f);
  EXPECT_GT(shown.x, 0.05f) << "the first splat, 6.1 % behind, is in the blend";

  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int probed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    ZexelCells cells = empty();
    std::vector<std::pair<ivec2, float>> splats;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (unit(rng) < 0.7f) splats.push_back({pixel + ivec2(dx, dy), 2.0f + 0.25f * unit(rng)});
    if (splats.empty()) continue;
    const int probe = int(unit(rng) * float(splats.size())) % int(splats.size());
    std::vector<vec2> landings;
    for (size_t k = 0; k < splats.size(); ++k) {
      const vec2 landed = vec2(splats[k].first) + vec2(unit(rng), unit(rng)) * 0.999f;
      landings.push_back(landed);
      put(cells, splats[k].first, landed, splats[k].second, int(k) == probe ? red : green);
    }
    int covering = 0;
    for (const vec2& landed : landings) covering += shading::zexel_covers(landed, 3, pixel) ? 1 : 0;
    const vec4 g = gatherZexels(cells, o, pixel);
    if (g.w < 0.0f || g.x <= 0.0f) continue;  // the probe is not in the blend
    ++probed;
    EXPECT_LE(splats[size_t(probe)].second,
              g.w * std::pow(1.0f + o.tolerance, float(covering - 1)) * (1.0f + 1e-6f))
        << "trial " << trial;
  }
  EXPECT_GT(probed, 500);
}

// The hierarchy's level per tile, on a wall facing the reference camera: its zexels at the
// tile's level land at most the goal apart, and at one level coarser more than that (the level
// is the coarsest that keeps the splats closed).
TEST(ZexelTiles, LevelIsTheCoarsestWhoseZexelsLandWithinTheGoal) {
  const WarpScene w = warpScene(512, {640, 480});
  const WarpCamera out = cameraOf(w.outputs.front());
  ZexelSplatOptions o;
  o.rect = ivec4(0, 0, 640, 480);
  o.tile_level = 3;
  o.finest = 0;
  o.goal = 2.0f;
  const ZexelWarpSource source{w.levels.data(), int(w.levels.size()), 512, w.in};
  const ZexelTilePlan plan = planZexelTiles(source, out, o);
  int checked = 0, finer = 0, over = 0;
  for (size_t l = 0; l < plan.by_level.size(); ++l) {
    const int level = plan.finest + int(l);
    const int n = 1 << (o.tile_level - level);
    const WarpCamera in{shading::zexel_level_matrix(w.in.p, level), w.in.c};
    for (const ZexelTileWord& word : plan.by_level[l]) {
      // The largest gap between the tile's neighbouring zexels at its level and one coarser,
      // where both land on the same surface (within 1 % in distance).
      auto largest = [&](int lv, const WarpCamera& cam, int side) {
        const ivec2 first = zexelTileOf(word) * side;
        float gap = 0.0f;
        const ZexelMap2D& m = w.levels[size_t(lv)];
        for (int y = 0; y < side; ++y)
          for (int x = 0; x < side; ++x)
            for (ivec2 step : {ivec2(1, 0), ivec2(0, 1)}) {
              const ivec2 a = first + ivec2(x, y), b = a + step;
              if (b.x >= m.width || b.y >= m.height) continue;
              const vec4 la = landingOf(m, cam, out, a), lb = landingOf(m, cam, out, b);
              if (!(la.z > 0.0f) || !(lb.z > 0.0f) || std::abs(la.w - lb.w) > 0.01f * la.w)
                continue;
              gap = std::max(gap, glm::length(vec2(la) - vec2(lb)));
            }
        return gap;
      };
      const float at_level = largest(level, in, n);
      if (level > plan.finest) {
        // The plan measures gaps between the tiles' own zexels, 2^3 apart: within a tile the
        // warp's magnification still varies a little (measured: 3 of 2193 tiles above the goal,
        // by at most 28 %).
        EXPECT_LE(at_level, 1.3f * o.goal) << "level " << level;
        over += at_level > 1.05f * o.goal ? 1 : 0;
      }
      if (level < o.tile_level) {
        const WarpCamera coarser{shading::zexel_level_matrix(w.in.p, level + 1), w.in.c};
        finer += largest(level + 1, coarser, n / 2) > o.goal ? 1 : 0;
      }
      ++checked;
    }
  }
  std::printf(
      "%d tiles checked, %d above the goal, %d at a level finer than the tile's whose coarser "
      "level opens\n",
      checked, over, finer);
  EXPECT_GT(checked, 50);
  EXPECT_LE(over, checked / 100);
  EXPECT_GT(finer, 0);
}

}  // namespace
}  // namespace mirage::test
