// The kd-tree of one point set (the hybrid paper, §4): every inner node splits its points at
// the median of x, then each half at the median of y, then each quarter at the median of z —
// the paper's eight-way recursion — until a node holds at most `leaf_points` points or its
// largest extent is below `min_size`. Children are built in parallel (TBB). Node bounds are the
// tight bounds of their points. The build reorders the points so that every leaf is one
// contiguous range, which is how the splatting shader reads them, in Morton order within the
// leaf (coherent SIMD lanes; a stride through a leaf is a stratified subsample). The tree lives in
// the points' object space: rigid (indeed any affine) motion moves the query, never the tree.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/bounds.h"

namespace mirage {

struct KdTreeOptions {
  int leaf_points = 256;  // a node with at most this many points is a leaf
  float min_size = 0.0f;  // a node whose largest bounds extent is at most this is a leaf
};

struct KdNode {
  Bounds3 bounds;      // tight bounds of the node's points
  uint32_t begin = 0;  // the node's points: [begin, end) in the reordered set
  uint32_t end = 0;
  uint32_t first_child = 0;  // children are consecutive nodes
  uint8_t child_count = 0;   // 0: a leaf
  uint8_t depth = 0;         // eight-way levels below the root
  bool leaf() const { return child_count == 0; }
};

struct KdTreeStats {
  size_t nodes = 0, leaves = 0;
  double average_leaf_depth = 0.0;  // in eight-way levels, weighted by leaf
  int max_depth = 0;
  double points_per_leaf = 0.0;
  double build_ms = 0.0;
};

class KdTree {
 public:
  KdTree() = default;
  // Builds over `positions`; `order` receives the permutation (new index -> old index) that
  // makes leaves contiguous: reorder the point attributes with it.
  KdTree(std::span<const vec3> positions, const KdTreeOptions& options,
         std::vector<uint32_t>& order);

  const std::vector<KdNode>& nodes() const { return nodes_; }
  const KdNode& root() const { return nodes_.front(); }
  bool empty() const { return nodes_.empty(); }
  const KdTreeStats& stats() const { return stats_; }

 private:
  std::vector<KdNode> nodes_;
  KdTreeStats stats_;
};

}  // namespace mirage
