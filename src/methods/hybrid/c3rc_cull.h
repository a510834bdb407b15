// View-volume culling of kd-tree boxes for a C3RC (the hybrid paper, §5.2), conservative: a box
// holding a point with a projection is never culled.
//
// Two stages. (1) The hull: the view volume {v(w) + λ d(w)} lies inside the base triangle swept
// along the cone of the three rays (v(w) + Σ (λ w_k) d_k), a convex polyhedron, so every plane
// a·x = h with a·d_k ≤ 0 for all k and h = max a·v_k bounds it (makeC3rc keeps up to eight); a
// box entirely beyond one of those planes is out. Cheap, and it rejects most boxes.
//
// (2) The exact test. The points a C3RC projects (c3rc_project: a root 0 ≤ λ ≤ λmax with
// barycentrics in the simplex Δ) are V = F(P), the image of the prism P = Δ × [0, λmax] under the
// sweep F(w, λ) = Σ w_k (v_k + λ d_k). Proof that the test never culls a box B meeting V:
//  - B is connected, so it lies inside V or meets V's frontier ∂V (V is compact, so closed).
//  - ∂V ⊂ F(∂P) ∪ F(C), C the points inside P where F's Jacobian is singular: at any other
//    inside point the inverse function theorem maps a neighbourhood onto one of its image.
//  - F(∂P) is the base T(0), the far cap T(λmax) and the side walls S(α, λ) = v_i + α(v_j − v_i)
//    + λ(d_i + α(d_j − d_i)), α ∈ [0, 1].
//  - det DF(w, λ) = n(λ)·d(w) = Σ w_k s_k(λ), s_k = n(λ)·d_k (the sidedness of ray k to T(λ)).
//    Inside Δ it vanishes only where the s_k have mixed strict signs, or all vanish; where all
//    vanish and T(λ) has collapsed, T(λ) is the union of its edges, which lie on the walls.
// So B meets V only if one of these holds, and the test keeps B when any does:
//  (a) B lies inside V: then every corner projects; one corner is tested.
//  (b) B meets the base or (c) the far cap: triangle–box separating-axis tests.
//  (d) B meets a wall W. Take W with λ unbounded (it only grows). W is a piece of a hyperbolic
//      paraboloid or a plane; a plane cuts it in hyperbolas, parabolas or lines, never a closed
//      curve. Either W's boundary meets B — its base edge (in the base: (b)) or its two rays
//      (construction ray–box tests) — or W, unbounded, leaves B through a face, where its
//      section runs to the face's edges: one of B's 12 edges crosses W (a quadratic in α per
//      edge and wall; walls lying in a face's plane handled apart, keeping where unsure).
//  (e) B meets a fold F(C): C lies at the λ where the s_k are mixed (or all vanish with T(λ)
//      whole), which makeC3rc gathers into two intervals (C3rcData::folds: the pieces between
//      the sidedness quadratics' roots where the sides differ). Over a λ range [a, b] every
//      T(λ) lies in the convex hull of T(a) and T(b) (each vertex moves on a segment), so F(C)
//      lies in the hulls of the intervals' pieces; B is kept unless a separating axis (the box's
//      normals, the two triangles' normals, box axes × rays and × edges) parts it from each.
// Rounding: the box is widened by c3rc_box_margin, the corner test allows barycentrics down to
// −1e-4, the fold intervals are widened by 1e-4 (1 + λ), and every test keeps the box where a
// quantity it divides by vanishes. The paper's own two conditions (a corner, and face–wall
// curves crossing face edges) miss (b), (c), (e), rays through a box whose faces the walls cut in
// closed curves, and walls parallel to a face; its face–wall λ also drops the face's corner
// (docs/methods.md). NEAR_FOLD counts the boxes only (e) keeps (cull_fold_keeps).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/bounds.h"
#include "methods/hybrid/c3rc.h"
#include "methods/hybrid/kd_tree.h"

namespace mirage {

// The box lies entirely outside one of the C3RC's hull planes (C3rcData::hull).
bool hullRejects(const C3rcData& c, const Bounds3& box);
// The exact (conservative) test: false only when the box and the view volume are disjoint.
bool boxMeetsViewVolume(const C3rcData& c, const Bounds3& box);
// The same, as MIRAGE_C3RC_BOX_OUT, _MEETS or _NEAR_FOLD (kept by case (e) alone).
int classifyBox(const C3rcData& c, const Bounds3& box);

// Pieces of the exact test, exposed for tests.
bool triangleMeetsBox(const vec3& a, const vec3& b, const vec3& c, const Bounds3& box);
bool rayMeetsBox(const vec3& origin, const vec3& dir, const Bounds3& box);
bool segmentCrossesWall(const vec3& p, const vec3& q, const vec3& vi, const vec3& vj,
                        const vec3& di, const vec3& dj);

enum class Culling {
  kNone,   // every leaf (the naive baseline: every point through every C3RC)
  kHull,   // the hull planes only
  kInner,  // hull planes, then the exact test at inner nodes only (leaves: the hull planes)
  kExact,  // hull planes, then the exact test at every node
};

struct CullCounters {
  long long nodes_tested = 0;
  long long hull_rejects = 0;
  long long exact_rejects = 0;
  long long cone_rejects = 0;  // nodes whose points all face away (normal_cone.h)
  long long fold_keeps = 0;    // nodes the exact test keeps for a fold alone
  long long leaves_kept = 0;
  CullCounters& operator+=(const CullCounters& o) {
    nodes_tested += o.nodes_tested;
    hull_rejects += o.hull_rejects;
    exact_rejects += o.exact_rejects;
    cone_rejects += o.cone_rejects;
    fold_keeps += o.fold_keeps;
    leaves_kept += o.leaves_kept;
    return *this;
  }
};

// Appends the index of every leaf of `tree` that may hold a point the C3RC `c` (in the tree's
// space) projects. `cones` (when not empty): the nodes' normal cones (normal_cone.h), which drop
// the nodes whose points all face away from the C3RC's triangle — for a splatting that skips
// such points (--hybrid-backfaces cull); culling kNone tests nothing.
void cullLeaves(const KdTree& tree, const C3rcData& c, Culling culling, std::span<const vec4> cones,
                std::vector<uint32_t>& leaves, CullCounters& counters);

}  // namespace mirage
