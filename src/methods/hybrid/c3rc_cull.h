// View-volume culling of kd-tree boxes for a C3RC (the hybrid paper, §5.2), conservative: a box
// holding a point with a projection is never culled.
//
// Two stages. (1) The hull: the view volume {v(w) + λ d(w)} lies inside the base triangle swept
// along the cone of the three rays (v(w) + Σ (λ w_k) d_k), a convex polyhedron, so every plane
// a·x = h with a·d_k ≤ 0 for all k and h = max a·v_k bounds it (makeC3rc keeps up to eight); a
// box entirely beyond one of those planes is out. Cheap, and it rejects most boxes. (2) The exact
// test, the paper's conditions made complete: a box meets the view volume if a corner of it
// projects (the box is inside), or the base triangle meets it, or a construction ray (λ ≥ 0) meets
// it, or one of its 12 edges crosses one of the 3 side walls S(α, λ) = v_i + α(v_j − v_i) + λ(d_i +
// α(d_j − d_i)), α ∈ [0, 1], λ ≥ 0 (a quadratic per edge and wall). Otherwise the boundary of the
// view volume misses the box and the box is not inside it: the two are disjoint. The paper's own
// two conditions (a corner, and face–wall curves crossing face edges) miss a wall entering a box
// through a face without crossing its edges, a box straddling the base, λ < 0 and walls parallel
// to a face; the ray, triangle and edge–wall tests cover those.
#pragma once

#include <cstdint>
#include <vector>

#include "core/bounds.h"
#include "methods/hybrid/c3rc.h"
#include "methods/hybrid/kd_tree.h"

namespace mirage {

// The box lies entirely outside one of the C3RC's hull planes (C3rcData::hull).
bool hullRejects(const C3rcData& c, const Bounds3& box);
// The exact (conservative) test: false only when the box and the view volume are disjoint.
bool boxMeetsViewVolume(const C3rcData& c, const Bounds3& box);

// Pieces of the exact test, exposed for tests.
bool triangleMeetsBox(const vec3& a, const vec3& b, const vec3& c, const Bounds3& box);
bool rayMeetsBox(const vec3& origin, const vec3& dir, const Bounds3& box);
bool segmentCrossesWall(const vec3& p, const vec3& q, const vec3& vi, const vec3& vj,
                        const vec3& di, const vec3& dj);

enum class Culling {
  kNone,   // every leaf (the naive baseline: every point through every C3RC)
  kHull,   // the hull planes only
  kExact,  // hull planes, then the exact test
};

struct CullCounters {
  long long nodes_tested = 0;
  long long hull_rejects = 0;
  long long exact_rejects = 0;
  long long leaves_kept = 0;
  CullCounters& operator+=(const CullCounters& o) {
    nodes_tested += o.nodes_tested;
    hull_rejects += o.hull_rejects;
    exact_rejects += o.exact_rejects;
    leaves_kept += o.leaves_kept;
    return *this;
  }
};

// Appends the index of every leaf of `tree` that may hold a point the C3RC `c` (in the tree's
// space) projects.
void cullLeaves(const KdTree& tree, const C3rcData& c, Culling culling,
                std::vector<uint32_t>& leaves, CullCounters& counters);

}  // namespace mirage
