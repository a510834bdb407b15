// The pyramid as the ssr tests define it, on the CPU: level 0 the depth buffer padded to
// `padded` with 1 ("nothing"), every level above the minimum of the up to four cells below; and
// beside it the farthest drawn depths' behind limits (0 where none is drawn), every level above
// the maximum of the cells below.
#pragma once

#include <algorithm>
#include <vector>

#include "core/math.h"

namespace mirage::test {

// `depth` (screen.x * screen.y, rows in order) in a padded.x * padded.y buffer of 1.
inline std::vector<float> paddedDepth(const std::vector<float>& depth, ivec2 screen, ivec2 padded) {
  std::vector<float> out(size_t(padded.x * padded.y), 1.0f);
  for (int y = 0; y < screen.y; ++y)
    for (int x = 0; x < screen.x; ++x)
      out[size_t(y * padded.x + x)] = depth[size_t(y * screen.x + x)];
  return out;
}

// The level of `size` above `below` (of `below_size`): each cell `combine` of the cells
// (2x + i, 2y + j), i, j in {0, 1}, that exist below, starting from `empty`.
template <typename Combine>
std::vector<float> levelAbove(const std::vector<float>& below, ivec2 below_size, ivec2 size,
                              float empty, Combine combine) {
  std::vector<float> level(size_t(size.x * size.y), empty);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      float m = empty;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          if (2 * x + i < below_size.x && 2 * y + j < below_size.y)
            m = combine(m, below[size_t((2 * y + j) * below_size.x + 2 * x + i)]);
      level[size_t(y * size.x + x)] = m;
    }
  return level;
}

// The nearest depths: the minimum of the cells below (1 where none exists).
inline std::vector<float> minLevelAbove(const std::vector<float>& below, ivec2 below_size,
                                        ivec2 size) {
  return levelAbove(below, below_size, size, 1.0f, [](float a, float b) { return std::min(a, b); });
}

// The farthest drawn depths (their behind limits): the maximum of the cells below (0 where
// none is drawn).
inline std::vector<float> maxLevelAbove(const std::vector<float>& below, ivec2 below_size,
                                        ivec2 size) {
  return levelAbove(below, below_size, size, 0.0f, [](float a, float b) { return std::max(a, b); });
}

}  // namespace mirage::test
