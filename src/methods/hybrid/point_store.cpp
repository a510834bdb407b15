#include "methods/hybrid/point_store.h"

#include "core/timer.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/normal_cone.h"

namespace mirage {

PointStore::PointStore(const Scene& scene, const PointSetOptions& options,
                       const KdTreeOptions& tree_options) {
  Stopwatch sample;
  std::vector<PointSet> sets = samplePoints(scene, pointSampledInstances(scene), options);
  sample_ms_ = sample.ms();
  for (const PointSet& s : sets) count_ += s.size();
  Stopwatch build;
  for (PointSet& set : sets) {
    PointCloud cloud;
    // A leaf-size floor relative to the object, so that a dense cluster stops splitting.
    Bounds3 b;
    for (const vec3& p : set.positions) b.extend(p);
    KdTreeOptions o = tree_options;
    o.min_size = tree_options.min_size * glm::length(b.extent());
    std::vector<uint32_t> order;
    cloud.tree = KdTree(set.positions, o, order);
    set.permute(order);
    cloud.cones = normalCones(
        cloud.tree, set.closed ? std::span<const vec3>(set.normals) : std::span<const vec3>());
    cloud.points = std::move(set);
    clouds_.push_back(std::move(cloud));
  }
  build_ms_ = build.ms();
  uint32_t offset = 0;
  for (PointCloud& c : clouds_) {
    c.offset = offset;
    offset += uint32_t(c.points.size());
  }
}

void PointStore::bind(GLuint positions, GLuint attributes) {
  if (!uploaded_) {
    std::vector<vec4> where;
    std::vector<shading::PointAttributes> what;
    where.reserve(count_);
    what.reserve(count_);
    for (const PointCloud& c : clouds_)
      for (size_t i = 0; i < c.points.size(); ++i) {
        where.push_back(vec4(c.points.positions[i], float(c.points.instance)));
        what.push_back({vec4(c.points.normals[i], c.points.spacings[i]),
                        vec4(c.points.albedo[i], c.points.closed ? 1.0f : 0.0f)});
      }
    if (where.empty()) {
      where.emplace_back(0.0f);
      what.emplace_back();
    }
    positions_.upload(std::span<const vec4>(where));
    attributes_.upload(std::span<const shading::PointAttributes>(what));
    uploaded_ = true;
  }
  positions_.bindBase(GL_SHADER_STORAGE_BUFFER, positions);
  attributes_.bindBase(GL_SHADER_STORAGE_BUFFER, attributes);
}

size_t PointStore::leafCount() const {
  size_t n = 0;
  for (const PointCloud& c : clouds_) n += c.tree.stats().leaves;
  return n;
}

long long PointStore::largestLeaf() const {
  long long most = 0;
  for (const PointCloud& c : clouds_)
    for (const KdNode& node : c.tree.nodes())
      if (node.leaf()) most = std::max<long long>(most, node.end - node.begin);
  return most;
}

double PointStore::averageLeafDepth() const {
  double sum = 0.0;
  size_t leaves = leafCount();
  for (const PointCloud& c : clouds_)
    sum += c.tree.stats().average_leaf_depth * double(c.tree.stats().leaves);
  return leaves ? sum / double(leaves) : 0.0;
}

double PointStore::pointsPerLeaf() const {
  size_t leaves = leafCount();
  return leaves ? double(count_) / double(leaves) : 0.0;
}

}  // namespace mirage
