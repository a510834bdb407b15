#include "methods/hybrid/normal_cone.h"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace mirage {

namespace {

// Rounding slack on the cosine (the cone widens by at least 1e-4 rad), so that a normal on the
// rim stays inside whatever the rounding of the axis.
constexpr float kCosineSlack = 1e-4f;

vec4 coneOf(std::span<const vec3> normals) {
  vec3 sum(0.0f);
  for (const vec3& n : normals) sum += n;
  const float length = glm::length(sum);
  // A mean shorter than this leaves the axis to rounding: no cone.
  if (!(length > 1e-3f * float(normals.size()))) return vec4(0.0f, 0.0f, 0.0f, kNoNormalCone);
  const vec3 axis = sum / length;
  float lowest = 1.0f;
  for (const vec3& n : normals) lowest = std::min(lowest, glm::dot(axis, n));
  const float cosine = lowest - kCosineSlack;
  return vec4(axis, cosine < -1.0f ? kNoNormalCone : cosine);
}

}  // namespace

std::vector<vec4> normalCones(const KdTree& tree, std::span<const vec3> normals) {
  const std::vector<KdNode>& nodes = tree.nodes();
  std::vector<vec4> cones(nodes.size(), vec4(0.0f, 0.0f, 0.0f, kNoNormalCone));
  if (normals.empty()) return cones;
  tbb::parallel_for(size_t(0), nodes.size(), [&](size_t i) {
    const KdNode& node = nodes[i];
    if (node.end > node.begin)
      cones[i] = coneOf(normals.subspan(node.begin, node.end - node.begin));
  });
  return cones;
}

}  // namespace mirage
