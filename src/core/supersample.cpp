#include "core/supersample.h"

#include <algorithm>
#include <array>

#include "core/check.h"

namespace mirage {

namespace {

void checkFactor(ivec2 size, int n, const char* what) {
  if (n < 1 || n > kMaxSsaa || size.x % n != 0 || size.y % n != 0)
    throwRuntime("{}: a {}x{} image cannot be reduced by {} (allowed 1..{}, dividing both sides)",
                 what, size.x, size.y, n, kMaxSsaa);
}

// The most frequent id of the n x n block of output pixel (x, y).
uint32_t blockMajority(const IdImage& ids, int n, int x, int y) {
  std::array<uint32_t, kMaxSsaa * kMaxSsaa> block{};
  size_t count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) block[count++] = ids(x * n + i, y * n + j);
  return mostFrequent(std::span(block.data(), count));
}

}  // namespace

uint32_t mostFrequent(std::span<uint32_t> values) {
  MIRAGE_CHECK(!values.empty());
  std::sort(values.begin(), values.end());
  uint32_t best = values.front();
  size_t best_run = 0;
  for (size_t start = 0; start < values.size();) {
    size_t end = start;
    while (end < values.size() && values[end] == values[start]) ++end;
    if (end - start > best_run) {  // strictly more: the first (smallest) value wins a tie
      best = values[start];
      best_run = end - start;
    }
    start = end;
  }
  return best;
}

Image boxDownsample(const Image& image, int n) {
  checkFactor(image.size(), n, "boxDownsample");
  if (n == 1) return image;
  const int w = image.width() / n, h = image.height() / n;
  Image out(w, h);
  // Summed in double: a block of equal values averages back to exactly that value.
  const double weight = 1.0 / double(n * n);
  const int centre = n / 2;  // the sub-pixel whose centre is nearest the pixel centre
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) sum += glm::dvec3(vec3(image(x * n + i, y * n + j)));
      out(x, y) = vec4(vec3(sum * weight), image(x * n + centre, y * n + centre).w);
    }
  return out;
}

IdImage majorityDownsample(const IdImage& ids, int n) {
  checkFactor(ids.size(), n, "majorityDownsample");
  if (n == 1) return ids;
  IdImage out(ids.width() / n, ids.height() / n);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) out(x, y) = blockMajority(ids, n, x, y);
  return out;
}

}  // namespace mirage
