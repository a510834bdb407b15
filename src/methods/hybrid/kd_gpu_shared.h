// The kd-trees and the culling state as the GPU culling (hybrid_cull.comp, --hybrid-cull-on gpu)
// sees them: every cloud's nodes in one flat array, uploaded once per point store, with point
// ranges in the shared point buffer and child indices into the flat array.
#ifndef MIRAGE_METHODS_HYBRID_KD_GPU_SHARED_H
#define MIRAGE_METHODS_HYBRID_KD_GPU_SHARED_H

#include "shading/glsl_compat.h"

// Storage bindings of the culling pass. It reads the object-space C3RCs at
// MIRAGE_BIND_HYBRID_C3RCS and writes the work items at MIRAGE_BIND_HYBRID_ITEMS (hybrid_shared.h).
#define MIRAGE_BIND_HYBRID_KD_NODES 9       // KdNodeGpu[]: every cloud's nodes
#define MIRAGE_BIND_HYBRID_KD_ROOTS 10      // uint[]: each cloud's root in the flat array, or
#define MIRAGE_KD_NO_ROOT 0xFFFFFFFFu       // an empty cloud
#define MIRAGE_BIND_HYBRID_KD_STATE 11      // uint[MIRAGE_KD_STATE_SIZE], below
#define MIRAGE_BIND_HYBRID_KD_QUEUE_IN 12   // uvec2[]: (C3RC-cloud pair, node) to test
#define MIRAGE_BIND_HYBRID_KD_QUEUE_OUT 13  // uvec2[]: the children of the kept inner nodes

// The state words: items (= leaves kept) and queue entries appended (either may exceed its
// buffer's capacity: the caller grows it and reruns the level), then the culling's counters.
#define MIRAGE_KD_STATE_ITEMS 0
#define MIRAGE_KD_STATE_QUEUED 1
#define MIRAGE_KD_STATE_TESTED 2
#define MIRAGE_KD_STATE_HULL_REJECTS 3
#define MIRAGE_KD_STATE_EXACT_REJECTS 4
#define MIRAGE_KD_STATE_FOLD_KEEPS 5
#define MIRAGE_KD_STATE_CONE_REJECTS 6
#define MIRAGE_KD_STATE_POINTS 7  // the points of the items written (the splatting checks it projected them)
#define MIRAGE_KD_STATE_SIZE 8

// The culling modes (Culling in c3rc_cull.h).
#define MIRAGE_KD_CULL_NONE 0
#define MIRAGE_KD_CULL_HULL 1
#define MIRAGE_KD_CULL_INNER 2
#define MIRAGE_KD_CULL_EXACT 3

#define MIRAGE_KD_CULL_GROUP 64  // invocations per workgroup: one queue entry each

// The work item's w for the splat pass: floatBitsToInt(1.0f), a level-of-detail stride of 1.
#define MIRAGE_KD_ITEM_W 0x3f800000

SHARED_BEGIN

struct KdNodeGpu {
  vec4 lo;  // xyz: the node's bounds (object space); w unused
  vec4 hi;
  uvec4 range;  // x, y: [begin, end) in the shared point buffer; z: first child (flat index);
                // w: child count (0: a leaf)
  vec4 cone;    // the normal cone of its points (normal_cone.h)
};

SHARED_END

#ifndef MIRAGE_GLSL
static_assert(sizeof(mirage::shading::KdNodeGpu) == 64, "KdNodeGpu layout (std430)");
#endif

#endif  // MIRAGE_METHODS_HYBRID_KD_GPU_SHARED_H
