// The normal cones of a point cloud's kd-tree nodes: for every node, an axis and the cosine of
// the widest angle between it and the normal of any point in the node. A node whose cone, over
// its box, faces away from all three corners of a reflector triangle holds only points the
// splatting would skip as facing away (hybrid_faces_away), so the culling drops it whole
// (c3rc_cone_faces_away in c3rc_cull_shared.h) — and the level of detail no longer spends its
// budget on them.
#pragma once

#include <span>
#include <vector>

#include "core/math.h"
#include "methods/hybrid/kd_tree.h"

namespace mirage {

// A cone that culls nothing: w below −1, no cosine (an open surface keeps its back faces).
inline constexpr float kNoNormalCone = -2.0f;

// Per node of `tree` (same indices): xyz the unit axis, w the cosine of the half-angle, widened a
// little for rounding; kNoNormalCone where the normals spread over more than a hemisphere's worth
// (their mean vanishes) or where `normals` is empty.
std::vector<vec4> normalCones(const KdTree& tree, std::span<const vec3> normals);

}  // namespace mirage
