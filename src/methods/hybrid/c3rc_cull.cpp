#include "methods/hybrid/c3rc_cull.h"

#include "core/check.h"
#include "methods/hybrid/c3rc_cull_shared.h"

namespace mirage {

// The tests themselves are in c3rc_cull_shared.h, which the GPU culling (hybrid_cull.comp) runs
// as well.

bool hullRejects(const C3rcData& c, const Bounds3& box) {
  return shading::c3rc_hull_rejects(c, box.lo, box.hi);
}

bool triangleMeetsBox(const vec3& a, const vec3& b, const vec3& c, const Bounds3& box) {
  return shading::c3rc_triangle_meets_box(a, b, c, box.lo, box.hi);
}

bool rayMeetsBox(const vec3& origin, const vec3& dir, const Bounds3& box) {
  return shading::c3rc_ray_meets_box(origin, dir, box.lo, box.hi);
}

bool segmentCrossesWall(const vec3& p, const vec3& q, const vec3& vi, const vec3& vj,
                        const vec3& di, const vec3& dj) {
  return shading::c3rc_segment_crosses_wall(p, q, vi, vj, di, dj);
}

bool boxMeetsViewVolume(const C3rcData& c, const Bounds3& box) {
  return shading::c3rc_box_meets_view_volume(c, box.lo, box.hi);
}

int classifyBox(const C3rcData& c, const Bounds3& box) {
  return shading::c3rc_classify_box(c, box.lo, box.hi);
}

void cullLeaves(const KdTree& tree, const C3rcData& c, Culling culling, std::span<const vec4> cones,
                std::vector<uint32_t>& leaves, CullCounters& counters) {
  if (tree.empty()) return;
  MIRAGE_CHECK(cones.empty() || cones.size() == tree.nodes().size());
  const std::vector<KdNode>& nodes = tree.nodes();
  uint32_t stack[64 * 8];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const KdNode& node = nodes[index];
    if (culling != Culling::kNone) {
      ++counters.nodes_tested;
      if (hullRejects(c, node.bounds)) {
        ++counters.hull_rejects;
        continue;
      }
      if (!cones.empty() &&
          shading::c3rc_cone_faces_away(cones[index], node.bounds.lo, node.bounds.hi, vec3(c.v0),
                                        vec3(c.v1), vec3(c.v2))) {
        ++counters.cone_rejects;
        continue;
      }
      if (culling == Culling::kExact || (culling == Culling::kInner && !node.leaf())) {
        const int kind = classifyBox(c, node.bounds);
        if (kind == MIRAGE_C3RC_BOX_OUT) {
          ++counters.exact_rejects;
          continue;
        }
        if (kind == MIRAGE_C3RC_BOX_NEAR_FOLD) ++counters.fold_keeps;
      }
    }
    if (node.leaf()) {
      leaves.push_back(index);
      ++counters.leaves_kept;
      continue;
    }
    for (uint32_t k = 0; k < node.child_count; ++k) stack[top++] = node.first_child + k;
  }
}

}  // namespace mirage
