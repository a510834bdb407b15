// Method `ssr`'s march through the hierarchical-Z pyramid (the very code its shader runs,
// methods/ssr/ssr_march_shared.h) against a brute-force march over every pixel of the depth
// buffer, on random depth buffers and random rays: the pyramid may only skip cells in which no
// pixel can be hit, so both must find the same first hit, pixel for pixel.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/math.h"

namespace mirage::shading {
namespace {
// The pyramid the march reads: level 0 the depth buffer padded to powers of two with 1
// ("nothing"), each level above the minimum of the four cells below (its definition); beside it
// the behind limits of the farthest drawn depths (0: nothing drawn), each level the maximum of
// the four below.
struct CpuPyramid {
  std::vector<std::vector<float>> levels, far_levels;
  std::vector<ivec2> sizes;
  vec2 at(int level, int x, int y) const {
    const ivec2 s = sizes[size_t(level)];
    if (x < 0 || y < 0 || x >= s.x || y >= s.y) return vec2(1.0f, 0.0f);
    const size_t i = size_t(y * s.x + x);
    return vec2(levels[size_t(level)][i], far_levels[size_t(level)][i]);
  }
};
CpuPyramid g_pyramid;
}  // namespace
inline vec2 ssr_cell(int level, int x, int y) {
  return g_pyramid.at(level, x, y);
}
}  // namespace mirage::shading

#include "methods/ssr/ssr_march_shared.h"

#include "methods/ssr/hiz_pyramid.h"
#include "support/min_pyramid.h"

namespace mirage::test {
namespace {

namespace sh = shading;

constexpr float kNear = 0.1f, kFar = 100.0f, kThickness = 0.5f;

// Level 0's behind limits: each drawn depth's window depth kThickness behind it, 0 where
// nothing is drawn.
std::vector<float> behindLimits(const std::vector<float>& padded) {
  std::vector<float> out(padded.size());
  for (size_t i = 0; i < padded.size(); ++i)
    out[i] = sh::ssr_behind_limit(padded[i], kThickness, kNear, kFar);
  return out;
}

sh::CpuPyramid buildPyramid(const std::vector<float>& depth, ivec2 size) {
  sh::CpuPyramid p;
  ivec2 s = HiZPyramid::paddedSize(size);
  p.levels.push_back(paddedDepth(depth, size, s));
  p.far_levels.push_back(behindLimits(p.levels.back()));
  p.sizes.push_back(s);
  while (s.x > 1 || s.y > 1) {
    const ivec2 below = s;
    s = glm::max(s / 2, ivec2(1));
    p.levels.push_back(minLevelAbove(p.levels.back(), below, s));
    p.far_levels.push_back(maxLevelAbove(p.far_levels.back(), below, s));
    p.sizes.push_back(s);
  }
  return p;
}

// A depth buffer of random rectangles (sloped planes of depth) over "nothing" (1).
std::vector<float> randomDepth(ivec2 size, std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> depth(size_t(size.x * size.y), 1.0f);
  for (int r = 0; r < 24; ++r) {
    const int x0 = int(unit(rng) * float(size.x)), y0 = int(unit(rng) * float(size.y));
    const int w = 1 + int(unit(rng) * float(size.x) * 0.4f),
              h = 1 + int(unit(rng) * float(size.y) * 0.4f);
    const float base = 0.90f + 0.099f * unit(rng);
    const float sx = (unit(rng) - 0.5f) * 1e-3f, sy = (unit(rng) - 0.5f) * 1e-3f;
    for (int y = y0; y < std::min(size.y, y0 + h); ++y)
      for (int x = x0; x < std::min(size.x, x0 + w); ++x) {
        const float d = std::clamp(base + sx * float(x - x0) + sy * float(y - y0), 0.0f, 0.9999f);
        float& at = depth[size_t(y * size.x + x)];
        at = std::min(at, d);
      }
  }
  return depth;
}

struct Hit {
  bool hit = false;
  ivec2 pixel{-1};
  int visited = 0;
};

// Brute force: every pixel the segment crosses, in order (Amanatides & Woo's grid walk), from
// the one after the start pixel; the first that passes the pixel test is the hit.
Hit bruteForce(vec3 from, vec3 to, const std::vector<float>& depth, ivec2 size,
               float thickness = kThickness) {
  Hit out;
  const vec2 d = vec2(to) - vec2(from);
  ivec2 cell(glm::floor(vec2(from)));
  const ivec2 step(d.x > 0 ? 1 : -1, d.y > 0 ? 1 : -1);
  auto boundary = [&](int axis) {
    const float dir = d[axis];
    if (dir == 0.0f) return kInfinity;
    const float edge = float(cell[axis] + (dir > 0 ? 1 : 0));
    return (edge - from[axis]) / dir;
  };
  const vec2 delta(d.x != 0 ? std::abs(1.0f / d.x) : kInfinity,
                   d.y != 0 ? std::abs(1.0f / d.y) : kInfinity);
  vec2 t_max(boundary(0), boundary(1));
  float t_entry = 0.0f;
  bool first = true;
  const float major = std::max(std::abs(d.x), std::abs(d.y));
  while (t_entry < 1.0f) {
    const float t_exit = std::min({t_max.x, t_max.y, 1.0f});
    // A pixel the ray only grazes, for less than 1/1024 pixel along its major axis, does not
    // count (the march steps that far past each cell's edge).
    const bool grazed = (t_exit - t_entry) * major < 1.0f / 1024.0f;
    if (!first && !grazed && cell.x >= 0 && cell.y >= 0 && cell.x < size.x && cell.y < size.y) {
      ++out.visited;
      const float za = from.z + t_entry * (to.z - from.z);
      const float zb = from.z + t_exit * (to.z - from.z);
      const float at = depth[size_t(cell.y * size.x + cell.x)];
      if (sh::ssr_pixel_hit(za, zb, at, sh::ssr_behind_limit(at, thickness, kNear, kFar))) {
        out.hit = true;
        out.pixel = cell;
        return out;
      }
    }
    first = false;
    // Through a corner exactly: on to the diagonal pixel (the ray only touches the two others).
    if (t_max.x == t_max.y) {
      cell += step;
      t_entry = t_max.x;
      t_max += delta;
    } else if (t_max.x < t_max.y) {
      cell.x += step.x;
      t_entry = t_max.x;
      t_max.x += delta.x;
    } else {
      cell.y += step.y;
      t_entry = t_max.y;
      t_max.y += delta.y;
    }
  }
  return out;
}

TEST(SsrMarch, FindsTheSamePixelAsAMarchOverEveryPixel) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const ivec2 size(203, 141);
  int rays = 0, hits = 0, differing = 0, at_threshold = 0;
  long pyramid_steps = 0, pixels_walked = 0;
  for (int buffer = 0; buffer < 6; ++buffer) {
    const std::vector<float> depth = randomDepth(size, rng);
    sh::g_pyramid = buildPyramid(depth, size);
    const int levels = int(sh::g_pyramid.levels.size());
    for (int r = 0; r < 2000; ++r) {
      // One draw per statement: the order of a call's arguments is the compiler's choice, and
      // the rays must be the same whichever compiler built the test.
      const float sx = unit(rng), sy = unit(rng);
      const ivec2 start(int(sx * float(size.x)), int(sy * float(size.y)));
      const float z0 =
          std::min(depth[size_t(start.y * size.x + start.x)], 0.95f + 0.04f * unit(rng));
      const vec3 from(float(start.x) + 0.5f, float(start.y) + 0.5f, z0);
      // An end anywhere on screen, nearer or farther: rays towards the eye and away from it.
      const float ex = unit(rng), ey = unit(rng), ez = unit(rng);
      const vec3 to(ex * (float(size.x) - 1e-3f), ey * (float(size.y) - 1e-3f),
                    std::clamp(z0 + (ez - 0.4f) * 0.1f, 0.0f, 0.99999f));
      ivec2 pixel;
      int steps = 0;
      const float t = sh::ssr_march(from, to, levels, 1 << 20, pixel, steps);
      const Hit want = bruteForce(from, to, depth, size);
      ++rays;
      hits += want.hit;
      pyramid_steps += steps;
      pixels_walked += want.visited;
      auto agrees = [&](const Hit& h) {
        return (t >= 0.0f) == h.hit && (!h.hit || (std::abs(pixel.x - h.pixel.x) <= 1 &&
                                                   std::abs(pixel.y - h.pixel.y) <= 1));
      };
      if (agrees(want)) continue;
      // A ray whose decisive pixel test is within 0.1 % of the thickness threshold may fall
      // either way (the pyramid tests a pixel from 1/1024 pixel past its edge): it must then
      // agree with the brute force at a thickness 0.1 % off.
      if (agrees(bruteForce(from, to, depth, size, kThickness * 0.999f)) ||
          agrees(bruteForce(from, to, depth, size, kThickness * 1.001f))) {
        ++at_threshold;
        continue;
      }
      if (++differing <= 5)
        ADD_FAILURE() << "ray (" << from.x << ", " << from.y << ", " << from.z << ") -> (" << to.x
                      << ", " << to.y << ", " << to.z << "): pyramid "
                      << (t >= 0 ? "hits" : "misses") << " at " << pixel.x << "," << pixel.y
                      << ", brute force " << (want.hit ? "hits" : "misses") << " at "
                      << want.pixel.x << "," << want.pixel.y;
    }
  }
  std::printf(
      "%d rays, %d hits, %d at the thickness threshold; pyramid cells visited %.1f per "
      "ray, pixels walked %.1f\n",
      rays, hits, at_threshold, double(pyramid_steps) / rays, double(pixels_walked) / rays);
  EXPECT_EQ(differing, 0) << "of " << rays << " rays";
  EXPECT_LE(at_threshold, rays / 1000) << "rays at the thickness threshold";
  // Both outcomes must be well represented for the comparison to mean something.
  EXPECT_GT(hits, rays / 5);
  EXPECT_LT(hits, rays - rays / 5);
}

// A ray over an empty depth buffer visits O(log n) cells, not one per pixel.
TEST(SsrMarch, SkipsEmptyStretchesInFewSteps) {
  const ivec2 size(1024, 512);
  sh::g_pyramid = buildPyramid(std::vector<float>(size_t(size.x * size.y), 1.0f), size);
  ivec2 pixel;
  int steps = 0;
  const float t = sh::ssr_march(vec3(3.5f, 3.5f, 0.5f), vec3(1020.0f, 500.0f, 0.6f),
                                int(sh::g_pyramid.levels.size()), 1 << 20, pixel, steps);
  EXPECT_LT(t, 0.0f);
  EXPECT_LT(steps, 64) << "cells visited over a 1,000-pixel empty ray";
}

TEST(SsrMarch, ThicknessLetsRaysPassBehindForegroundObjects) {
  // The projection's window depth of a view depth, written out: the oracle of
  // ssr_view_depth, ssr_window_depth and the behind limit.
  auto window = [](float view_depth) {
    return (kFar + kNear - 2.0f * kNear * kFar / view_depth) / (kFar - kNear) * 0.5f + 0.5f;
  };
  for (float v : {0.2f, 1.0f, 7.5f, 60.0f}) {
    EXPECT_NEAR(sh::ssr_view_depth(window(v), kNear, kFar), v, 1e-4f * v);
    EXPECT_NEAR(sh::ssr_window_depth(v, kNear, kFar), window(v), 1e-6f);
    EXPECT_NEAR(sh::ssr_behind_limit(window(v), kThickness, kNear, kFar), window(v + kThickness),
                1e-6f);
  }
  EXPECT_EQ(sh::ssr_behind_limit(1.0f, kThickness, kNear, kFar), 0.0f);  // nothing drawn
  // View depth 1 at the surface; a ray entering 0.4 behind it hits with thickness 0.5, one 0.6
  // behind does not; a ray crossing from the front always hits.
  const float d = window(1.0f);
  const float limit = sh::ssr_behind_limit(d, kThickness, kNear, kFar);
  EXPECT_TRUE(sh::ssr_pixel_hit(window(1.4f), window(1.5f), d, limit));
  EXPECT_FALSE(sh::ssr_pixel_hit(window(1.6f), window(1.7f), d, limit));
  EXPECT_TRUE(sh::ssr_pixel_hit(window(0.9f), window(3.0f), d, limit));
  EXPECT_FALSE(sh::ssr_pixel_hit(window(0.5f), window(0.9f), d, limit));
  EXPECT_FALSE(sh::ssr_pixel_hit(window(0.5f), window(3.0f), 1.0f, 0.0f));
}

}  // namespace
}  // namespace mirage::test
