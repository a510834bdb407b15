#include "methods/hybrid/kd_tree.h"

#include <algorithm>
#include <atomic>

#include <tbb/concurrent_vector.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include "core/timer.h"

namespace mirage {

namespace {

// Ranges smaller than this are built (and bounded) serially: a task costs more than the work.
constexpr size_t kSerialPoints = 8192;

struct Builder {
  std::span<const vec3> positions;
  std::vector<uint32_t>& index;
  KdTreeOptions options;
  tbb::concurrent_vector<KdNode> nodes;

  Bounds3 boundsOf(uint32_t begin, uint32_t end) const {
    auto extend = [&](const tbb::blocked_range<uint32_t>& r, Bounds3 b) {
      for (uint32_t i = r.begin(); i < r.end(); ++i) b.extend(positions[index[i]]);
      return b;
    };
    if (end - begin < kSerialPoints)
      return extend(tbb::blocked_range<uint32_t>(begin, end), Bounds3{});
    return tbb::parallel_reduce(tbb::blocked_range<uint32_t>(begin, end, 4096), Bounds3{}, extend,
                                [](Bounds3 a, const Bounds3& b) {
                                  a.extend(b);
                                  return a;
                                });
  }

  static uint32_t spread10(uint32_t v) {  // 10 bits to every third of 30
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    return (v | (v << 2)) & 0x09249249u;
  }

  void sortMorton(uint32_t begin, uint32_t end, const Bounds3& bounds) {
    const vec3 scale = 1023.0f / glm::max(bounds.extent(), vec3(1e-30f));
    // (code << 32 | index) keys: one integer sort, no allocation after a thread's first leaf.
    thread_local std::vector<uint64_t> keys;
    keys.clear();
    for (uint32_t k = begin; k < end; ++k) {
      const uvec3 c = uvec3(glm::clamp((positions[index[k]] - bounds.lo) * scale, 0.0f, 1023.0f));
      const uint32_t code = spread10(c.x) | (spread10(c.y) << 1) | (spread10(c.z) << 2);
      keys.push_back((uint64_t(code) << 32) | index[k]);
    }
    std::sort(keys.begin(), keys.end());
    for (uint32_t k = begin; k < end; ++k) index[k] = uint32_t(keys[k - begin]);
  }

  // Splits [begin, end) at the median of `axis` in place; returns the split point.
  uint32_t splitMedian(uint32_t begin, uint32_t end, int axis) {
    uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(
        index.begin() + begin, index.begin() + mid, index.begin() + end,
        [&](uint32_t a, uint32_t b) { return positions[a][axis] < positions[b][axis]; });
    return mid;
  }

  void build(size_t node_index, uint32_t begin, uint32_t end, uint8_t depth) {
    KdNode node;
    node.begin = begin;
    node.end = end;
    node.depth = depth;
    node.bounds = boundsOf(begin, end);
    const vec3 e = node.bounds.extent();
    const float largest = std::max({e.x, e.y, e.z});
    if (end - begin <= uint32_t(options.leaf_points) || largest <= options.min_size ||
        depth >= 60) {
      // A leaf's points in Morton order within its bounds: neighbours in the leaf are neighbours
      // in space (the splatting's SIMD lanes then take similar paths), and a stride through
      // the leaf is a spatially stratified subsample (the level of detail).
      sortMorton(begin, end, node.bounds);
      nodes[node_index] = node;
      return;
    }
    // Eight ranges: x median, then y medians of the halves, then z medians of the quarters.
    uint32_t cut[9];
    cut[0] = begin;
    cut[8] = end;
    cut[4] = splitMedian(begin, end, 0);
    for (int h = 0; h < 2; ++h) cut[2 + 4 * h] = splitMedian(cut[4 * h], cut[4 * h + 4], 1);
    for (int q = 0; q < 4; ++q) cut[1 + 2 * q] = splitMedian(cut[2 * q], cut[2 * q + 2], 2);
    int children = 0;
    for (int c = 0; c < 8; ++c) children += cut[c + 1] > cut[c] ? 1 : 0;
    auto first = nodes.grow_by(size_t(children));
    node.first_child = uint32_t(first - nodes.begin());
    node.child_count = uint8_t(children);
    nodes[node_index] = node;
    tbb::task_group tasks;
    uint32_t child = node.first_child;
    for (int c = 0; c < 8; ++c) {
      if (cut[c + 1] == cut[c]) continue;
      uint32_t b = cut[c], en = cut[c + 1], slot = child++;
      if (en - b >= kSerialPoints)
        tasks.run([this, slot, b, en, depth] { build(slot, b, en, uint8_t(depth + 1)); });
      else
        build(slot, b, en, uint8_t(depth + 1));
    }
    tasks.wait();
  }
};

}  // namespace

KdTree::KdTree(std::span<const vec3> positions, const KdTreeOptions& options,
               std::vector<uint32_t>& order) {
  Stopwatch watch;
  order.resize(positions.size());
  for (uint32_t i = 0; i < uint32_t(order.size()); ++i) order[i] = i;
  if (positions.empty()) return;
  Builder builder{positions, order, options, {}};
  builder.nodes.grow_by(1);
  builder.build(0, 0, uint32_t(positions.size()), 0);
  nodes_.assign(builder.nodes.begin(), builder.nodes.end());
  stats_.nodes = nodes_.size();
  double depth_sum = 0.0;
  for (const KdNode& n : nodes_) {
    if (!n.leaf()) continue;
    ++stats_.leaves;
    depth_sum += n.depth;
    stats_.max_depth = std::max(stats_.max_depth, int(n.depth));
  }
  stats_.average_leaf_depth = depth_sum / double(stats_.leaves);
  stats_.points_per_leaf = double(positions.size()) / double(stats_.leaves);
  stats_.build_ms = watch.ms();
}

}  // namespace mirage
