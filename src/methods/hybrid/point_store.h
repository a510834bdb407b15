// The hybrid method's point sets and their kd-trees, built once per scene (rigid motion needs
// neither rebuilt: points live in object space, the culling moves the query), and the storage
// buffers of every point in leaf order that the splatting shader reads (positions, and
// normals and albedos: hybrid_shared.h).
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "methods/hybrid/kd_tree.h"
#include "methods/hybrid/point_set.h"

namespace mirage {

struct PointCloud {
  PointSet points;
  KdTree tree;
  // Per tree node: the normal cone of its points (normal_cone.h); kNoNormalCone throughout for an
  // open surface, whose back-facing points are projected.
  std::vector<vec4> cones;
  uint32_t offset = 0;  // index of its first point in the shared buffer
};

class PointStore {
 public:
  PointStore(const Scene& scene, const PointSetOptions& points, const KdTreeOptions& tree);

  const std::vector<PointCloud>& clouds() const { return clouds_; }
  size_t pointCount() const { return count_; }
  // Uploads the buffers on first use; binds them.
  void bind(GLuint positions, GLuint attributes);

  double sampleMs() const { return sample_ms_; }
  // The kd-trees' build time, and the reordering of the points into leaf order.
  double buildMs() const { return build_ms_; }
  double averageLeafDepth() const;
  double pointsPerLeaf() const;
  size_t leafCount() const;
  // The most points a leaf of any tree holds (a work item of the GPU culling is one leaf).
  long long largestLeaf() const;

 private:
  std::vector<PointCloud> clouds_;
  size_t count_ = 0;
  double sample_ms_ = 0.0, build_ms_ = 0.0;
  gpu::Buffer positions_, attributes_;
  bool uploaded_ = false;
};

}  // namespace mirage
