// The backward phase's culling on the GPU (--hybrid-cull-on gpu; the paper's future work), one
// kd-tree level per dispatch: each invocation takes one (C3RC, cloud) pair's node from the queue
// (or, at the first level, the pair's root), tests it with the CPU culling's own tests
// (c3rc_cull_shared.h) on the C3RC moved into the cloud's space, and appends a kept leaf as a
// work item of the splatting pass and a kept inner node's children to the next level's queue.
// Not a stack per pair: llvmpipe ends any shader after 65,535 loop iterations in all (its loop
// limiter), which one pair's walk with the exact test's inner loops overruns; one node per
// invocation stays far below. Adjacent leaves are not merged into longer items (the CPU merges).
#include "methods/hybrid/c3rc_cull_shared.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/kd_gpu_shared.h"

layout(local_size_x = MIRAGE_KD_CULL_GROUP) in;

// [c3rc * u_cloud_count + cloud]: each C3RC in each cloud's object space.
layout(std430, binding = MIRAGE_BIND_HYBRID_C3RCS) readonly buffer C3rcBlock { C3rcData c3rcs[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_KD_NODES) readonly buffer NodeBlock {
  KdNodeGpu nodes[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_KD_ROOTS) readonly buffer RootBlock { uint roots[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_KD_QUEUE_IN) readonly buffer InBlock { uvec2 queue_in[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_KD_QUEUE_OUT) writeonly buffer OutBlock {
  uvec2 queue_out[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_ITEMS) writeonly buffer ItemBlock { ivec4 items[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_KD_STATE) buffer StateBlock { uint state[]; };

uniform int u_entry_count;     // queue entries (at the first level: pairs)
uniform int u_first_level;     // 1: entry i is pair i at its cloud's root
uniform int u_cloud_count;
uniform int u_culling;         // MIRAGE_KD_CULL_*
uniform int u_cull_backfaces;  // 1: drop the nodes whose normal cone faces away (normal_cone.h)
uniform int u_item_capacity;   // items beyond it are counted, not written
uniform int u_queue_capacity;  // the same for the next level's queue

void main() {
  uint entry = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * MIRAGE_KD_CULL_GROUP +
               gl_LocalInvocationID.x;
  if (entry >= uint(u_entry_count)) return;
  uint pair, index;
  if (u_first_level != 0) {
    pair = entry;
    index = roots[pair % uint(u_cloud_count)];
    if (index == MIRAGE_KD_NO_ROOT) return;
    if ((int(c3rcs[pair].info.z) & MIRAGE_C3RC_DEGENERATE) != 0) return;
  } else {
    pair = queue_in[entry].x;
    index = queue_in[entry].y;
  }
  KdNodeGpu node = nodes[index];
  if (u_culling != MIRAGE_KD_CULL_NONE) {
    C3rcData c = c3rcs[pair];
    atomicAdd(state[MIRAGE_KD_STATE_TESTED], 1u);
    if (c3rc_hull_rejects(c, node.lo.xyz, node.hi.xyz)) {
      atomicAdd(state[MIRAGE_KD_STATE_HULL_REJECTS], 1u);
      return;
    }
    if (u_cull_backfaces != 0 &&
        c3rc_cone_faces_away(node.cone, node.lo.xyz, node.hi.xyz, vec3(c.v0), vec3(c.v1),
                             vec3(c.v2))) {
      atomicAdd(state[MIRAGE_KD_STATE_CONE_REJECTS], 1u);
      return;
    }
    if (u_culling == MIRAGE_KD_CULL_EXACT ||
        (u_culling == MIRAGE_KD_CULL_INNER && node.range.w != 0u)) {
      int kind = c3rc_classify_box(c, node.lo.xyz, node.hi.xyz);
      if (kind == MIRAGE_C3RC_BOX_OUT) {
        atomicAdd(state[MIRAGE_KD_STATE_EXACT_REJECTS], 1u);
        return;
      }
      if (kind == MIRAGE_C3RC_BOX_NEAR_FOLD) atomicAdd(state[MIRAGE_KD_STATE_FOLD_KEEPS], 1u);
    }
  }
  if (node.range.w == 0u) {
    uint slot = atomicAdd(state[MIRAGE_KD_STATE_ITEMS], 1u);
    atomicAdd(state[MIRAGE_KD_STATE_POINTS], node.range.y - node.range.x);
    if (slot < uint(u_item_capacity))
      items[slot] = ivec4(int(pair) / u_cloud_count, int(node.range.x),
                          int(node.range.y - node.range.x), MIRAGE_KD_ITEM_W);
    return;
  }
  uint first = atomicAdd(state[MIRAGE_KD_STATE_QUEUED], node.range.w);
  if (first + node.range.w <= uint(u_queue_capacity))
    for (uint k = 0u; k < node.range.w; ++k) queue_out[first + k] = uvec2(pair, node.range.z + k);
}
