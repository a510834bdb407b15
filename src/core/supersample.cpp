#include "core/supersample.h"

#include <algorithm>
#include <array>
#include <vector>

namespace mirage {

namespace {

void checkFactor(ivec2 size, int n, const char* what) {
  if (n < 1 || n > kMaxSsaa || size.x % n != 0 || size.y % n != 0)
    throwRuntime("{}: a {}x{} image cannot be reduced by {} (allowed 1..{}, dividing both sides)",
                 what, size.x, size.y, n, kMaxSsaa);
}

// The most frequent of the block's ids and how many sub-pixels hold it; ties to the smaller id.
std::pair<uint32_t, int> blockMajority(const IdImage& ids, int n, int x, int y) {
  std::array<uint32_t, kMaxSsaa * kMaxSsaa> block{};
  int count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) block[size_t(count++)] = ids(x * n + i, y * n + j);
  std::sort(block.begin(), block.begin() + count);
  uint32_t best = block[0];
  int best_run = 0;
  for (int start = 0; start < count;) {
    int end = start;
    while (end < count && block[size_t(end)] == block[size_t(start)]) ++end;
    if (end - start > best_run) {  // strictly more: the first (smallest) id wins a tie
      best = block[size_t(start)];
      best_run = end - start;
    }
    start = end;
  }
  return {best, best_run};
}

}  // namespace

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
    for (int x = 0; x < out.width(); ++x) out(x, y) = blockMajority(ids, n, x, y).first;
  return out;
}

int blockDisagreement(const IdImage& ids, int n, int x, int y) {
  return n * n - blockMajority(ids, n, x, y).second;
}

}  // namespace mirage
