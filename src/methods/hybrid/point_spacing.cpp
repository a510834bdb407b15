#include "methods/hybrid/point_spacing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <tbb/parallel_for.h>

#include "core/check.h"

namespace mirage {

namespace {

// The points in a uniform grid of cubic cells, for neighbour queries: the points sorted by the
// key of their cell, and the unique keys with where each cell's points begin.
class PointGrid {
 public:
  PointGrid(std::span<const vec3> points, float cell) : cell_(cell) {
    origin_ = vec3(INFINITY);
    for (const vec3& p : points) origin_ = glm::min(origin_, p);
    std::vector<std::pair<uint64_t, uint32_t>> keyed(points.size());
    for (size_t i = 0; i < points.size(); ++i) keyed[i] = {key(cellOf(points[i])), uint32_t(i)};
    std::sort(keyed.begin(), keyed.end());
    order_.resize(points.size());
    for (size_t i = 0; i < keyed.size(); ++i) {
      order_[i] = keyed[i].second;
      if (i == 0 || keyed[i].first != keyed[i - 1].first) {
        keys_.push_back(keyed[i].first);
        begin_.push_back(uint32_t(i));
      }
    }
    begin_.push_back(uint32_t(keyed.size()));
    sorted_.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) sorted_[i] = points[order_[i]];
    // An open-addressing table from a cell's key to its place among the keys.
    size_t slots = 16;
    while (slots < 2 * keys_.size()) slots *= 2;
    table_.assign(slots, kEmpty);
    for (size_t k = 0; k < keys_.size(); ++k) {
      size_t at = slot(keys_[k]);
      while (table_[at] != kEmpty) at = (at + 1) & (table_.size() - 1);
      table_[at] = uint32_t(k);
    }
  }

  ivec3 cellOf(const vec3& p) const {
    return glm::clamp(ivec3(glm::floor((p - origin_) / cell_)), ivec3(0), ivec3(kMaxCell));
  }
  float cell() const { return cell_; }
  size_t cells() const { return keys_.size(); }
  // The points of cell k: places s in [begin, end) of the grid's order, point order(s).
  uint32_t begin(size_t k) const { return begin_[k]; }
  uint32_t end(size_t k) const { return begin_[k + 1]; }
  uint32_t order(uint32_t s) const { return order_[s]; }
  const vec3& sorted(uint32_t s) const { return sorted_[s]; }

  // The ranges of places of the cells within `shells` cells of cell c along each axis.
  void neighbourhood(const ivec3& c, int shells, std::vector<uvec2>& ranges) const {
    ranges.clear();
    for (int z = c.z - shells; z <= c.z + shells; ++z)
      for (int y = c.y - shells; y <= c.y + shells; ++y)
        for (int x = c.x - shells; x <= c.x + shells; ++x) {
          if (x < 0 || y < 0 || z < 0 || x > kMaxCell || y > kMaxCell || z > kMaxCell) continue;
          const uint32_t k = find(key({x, y, z}));
          if (k != kEmpty) ranges.push_back({begin_[k], begin_[k + 1]});
        }
  }
  ivec3 cellOfKey(size_t k) const {
    const uint64_t v = keys_[k];
    return ivec3(int(v & kMaxCell), int((v >> 21) & kMaxCell), int((v >> 42) & kMaxCell));
  }

 private:
  static constexpr int kMaxCell = (1 << 21) - 1;
  static constexpr uint32_t kEmpty = 0xFFFFFFFFu;
  static uint64_t key(ivec3 c) {
    return uint64_t(c.x) | (uint64_t(c.y) << 21) | (uint64_t(c.z) << 42);
  }
  size_t slot(uint64_t k) const {
    return size_t((k * 0x9E3779B97F4A7C15ull) >> 32) & (table_.size() - 1);
  }
  // The place of cell `k` among the keys, or kEmpty where no point lies in it.
  uint32_t find(uint64_t k) const {
    for (size_t at = slot(k);; at = (at + 1) & (table_.size() - 1)) {
      const uint32_t e = table_[at];
      if (e == kEmpty || keys_[e] == k) return e;
    }
  }

  float cell_;
  vec3 origin_{0.0f};
  std::vector<uint64_t> keys_;
  std::vector<uint32_t> begin_, order_, table_;
  std::vector<vec3> sorted_;  // the points in the grid's order
};

// The k smallest of the distances offered, kept sorted.
struct Nearest {
  std::array<float, kSpacingNeighbours> d;
  int count = 0;
  void offer(float v) {
    if (count < kSpacingNeighbours) {
      d[size_t(count++)] = v;
    } else if (v < d.back()) {
      d.back() = v;
    } else {
      return;
    }
    for (int i = count - 1; i > 0 && d[size_t(i)] < d[size_t(i - 1)]; --i)
      std::swap(d[size_t(i)], d[size_t(i - 1)]);
  }
};

// An indexed binary max-heap of weights, whose entries can be lowered in place.
class WeightHeap {
 public:
  explicit WeightHeap(std::vector<float> weights) : weight_(std::move(weights)) {
    heap_.resize(weight_.size());
    where_.resize(weight_.size());
    std::iota(heap_.begin(), heap_.end(), 0u);
    for (size_t i = 0; i < heap_.size(); ++i) where_[i] = uint32_t(i);
    for (size_t i = heap_.size() / 2; i-- > 0;) down(i);
  }
  bool empty() const { return heap_.empty(); }
  uint32_t top() const { return heap_.front(); }
  bool contains(uint32_t i) const { return where_[i] != kGone; }
  void pop() {
    const uint32_t gone = heap_.front();
    place(0, heap_.back());
    heap_.pop_back();
    where_[gone] = kGone;
    if (!heap_.empty()) down(0);
  }
  void lower(uint32_t i, float by) {
    weight_[i] -= by;
    down(where_[i]);
  }

 private:
  static constexpr uint32_t kGone = 0xFFFFFFFFu;
  // Ties by the lower index, so that the result is the same on every machine.
  bool above(uint32_t a, uint32_t b) const {
    return weight_[a] != weight_[b] ? weight_[a] > weight_[b] : a < b;
  }
  void place(size_t at, uint32_t i) {
    heap_[at] = i;
    where_[i] = uint32_t(at);
  }
  void down(size_t at) {
    for (;;) {
      size_t best = at;
      for (size_t c = 2 * at + 1; c <= 2 * at + 2 && c < heap_.size(); ++c)
        if (above(heap_[c], heap_[best])) best = c;
      if (best == at) return;
      const uint32_t a = heap_[at], b = heap_[best];
      place(at, b);
      place(best, a);
      at = best;
    }
  }

  std::vector<float> weight_;
  std::vector<uint32_t> heap_, where_;
};

}  // namespace

std::vector<float> neighbourSpacings(std::span<const vec3> positions, float mean_spacing,
                                     float most) {
  std::vector<float> out(positions.size(), most);
  if (positions.size() < 2 || !(mean_spacing > 0.0f)) return out;
  const PointGrid grid(positions, 1.5f * mean_spacing);
  // Shells out to `most` (beyond it every point takes `most`), and at most 1,024 of them.
  const int max_shells =
      int(std::clamp(std::ceil(double(most) / double(grid.cell())), 1.0, 1024.0));
  // Cell by cell: the neighbourhood's cells looked up once for all the cell's points; a point
  // whose neighbours lie farther looks again in wider shells.
  tbb::parallel_for(size_t(0), grid.cells(), [&](size_t k) {
    std::vector<uvec2> near, wider;
    const ivec3 c = grid.cellOfKey(k);
    grid.neighbourhood(c, 1, near);
    for (uint32_t s = grid.begin(k); s < grid.end(k); ++s) {
      const vec3 p = grid.sorted(s);
      // Every point within `shells` cells' width of p is in the cube of that many shells.
      for (int shells = 1; shells <= max_shells; ++shells) {
        if (shells > 1) grid.neighbourhood(c, shells, wider);
        Nearest nearest;
        for (const uvec2& r : shells > 1 ? wider : near)
          for (uint32_t t = r.x; t < r.y; ++t)
            if (t != s) nearest.offer(glm::length(grid.sorted(t) - p));
        if (nearest.count == kSpacingNeighbours &&
            nearest.d.back() <= float(shells) * grid.cell()) {
          out[grid.order(s)] = std::min(kSpacingScale * nearest.d.back(), most);
          break;
        }
      }
    }
  });
  return out;
}

std::vector<uint32_t> eliminateSamples(std::span<const vec3> candidates, size_t fixed,
                                       size_t target, double area) {
  MIRAGE_CHECK_LE(fixed, target);
  std::vector<uint32_t> kept(candidates.size());
  std::iota(kept.begin(), kept.end(), 0u);
  if (candidates.size() <= target || !(area > 0.0)) return kept;
  // The largest Poisson-disk radius of `target` points on the area, hexagonally packed; weights
  // reach twice it, and the paper's weight limiting keeps nearer pairs from dominating.
  const double r_max = std::sqrt(area / (2.0 * std::sqrt(3.0) * double(target)));
  const float d_max = float(2.0 * r_max);
  const double ratio = double(target) / double(candidates.size());
  const float d_min = d_max * float((1.0 - std::pow(ratio, 1.5)) * 0.65);
  const auto weight = [&](float d) {
    const float x = 1.0f - std::max(d, d_min) / d_max, x2 = x * x, x4 = x2 * x2;
    return x4 * x4;  // ^8, the paper's alpha
  };
  // Each candidate's neighbours within d_max and what each adds to its weight, found once, cell
  // by cell (each cell's pairs in a list of its own), then gathered into one array (CSR).
  const PointGrid grid(candidates, d_max);
  const size_t n = candidates.size();
  std::vector<std::vector<std::pair<uint32_t, float>>> by_cell(grid.cells());
  std::vector<uint32_t> first(n + 1, 0);
  tbb::parallel_for(size_t(0), grid.cells(), [&](size_t k) {
    std::vector<uvec2> ranges;
    grid.neighbourhood(grid.cellOfKey(k), 1, ranges);
    for (uint32_t s = grid.begin(k); s < grid.end(k); ++s) {
      const vec3 p = grid.sorted(s);
      for (const uvec2& r : ranges)
        for (uint32_t t = r.x; t < r.y; ++t) {
          const float d = glm::length(grid.sorted(t) - p);
          if (t != s && d < d_max) by_cell[k].push_back({grid.order(t), weight(d)});
        }
      first[grid.order(s) + 1] = uint32_t(by_cell[k].size());  // this point's end, for now
    }
  });
  // A point's pairs are consecutive within its cell's list: their counts, then where they go.
  std::vector<std::pair<uint32_t, float>> near;
  near.reserve(n * 8);
  std::vector<uint32_t> start(n), count(n);
  for (size_t k = 0; k < grid.cells(); ++k) {
    uint32_t at = 0;
    for (uint32_t s = grid.begin(k); s < grid.end(k); ++s) {
      const uint32_t i = grid.order(s), end = first[i + 1];
      start[i] = uint32_t(near.size());
      count[i] = end - at;
      near.insert(near.end(), by_cell[k].begin() + at, by_cell[k].begin() + end);
      at = end;
    }
    by_cell[k] = {};
  }
  std::vector<float> weights(n, 0.0f);
  for (size_t i = 0; i < n; ++i)
    for (uint32_t e = start[i]; e < start[i] + count[i]; ++e) weights[i] += near[e].second;
  // The fixed points crowd the others but are not removed: they stay out of the heap's reach.
  for (size_t i = 0; i < fixed; ++i) weights[i] = -INFINITY;
  WeightHeap heap(std::move(weights));
  for (size_t left = n; left > target; --left) {
    const uint32_t gone = heap.top();
    heap.pop();
    for (uint32_t e = start[gone]; e < start[gone] + count[gone]; ++e) {
      const auto [j, w] = near[e];
      if (j >= fixed && heap.contains(j)) heap.lower(j, w);
    }
  }
  kept.clear();
  for (uint32_t i = 0; i < candidates.size(); ++i)
    if (heap.contains(i)) kept.push_back(i);
  return kept;
}

}  // namespace mirage
