// The GPU path of the backward phase's culling (--hybrid-cull-on gpu, the hybrid paper's future
// work): the kd-trees uploaded once as one flat node buffer, and per frame the C3RCs moved into
// every cloud's space on the CPU and culled by hybrid_cull.comp, one tree level per dispatch,
// which writes the splatting pass's work items straight into a GPU buffer. The tests are the CPU
// culling's own (c3rc_cull_shared.h); kept leaves are not merged into longer items.
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "methods/hybrid/c3rc_cull.h"
#include "methods/hybrid/point_store.h"

namespace mirage {

struct KdGpuCullResult {
  size_t items = 0;  // work items in KdGpuCull::items()
  long long points = 0;  // the points they hold
  CullCounters cull;
  int dispatches = 0;         // one per tree level, and one more per buffer that had to grow
  double transform_ms = 0.0;  // moving the C3RCs into the clouds' spaces (CPU, TBB)
  double gpu_ms = 0.0;        // upload, dispatches, glFinish and the read-backs of the counts
};

class KdGpuCull {
 public:
  // Uploads every cloud's kd-tree; the store must outlive this.
  explicit KdGpuCull(const PointStore& store);

  // Culls the world-space C3RCs (a C3RC flagged MIRAGE_C3RC_DEGENERATE is skipped) against every
  // cloud at its current transform (`matrices`: every instance's); `cull_backfaces`: drop the
  // nodes whose normal cones face away (cullLeaves with the clouds' cones).
  KdGpuCullResult run(const std::vector<C3rcData>& c3rcs, const std::vector<mat4>& matrices,
                      Culling culling, bool cull_backfaces);

  // The item buffer of the last run: ivec4(C3RC, first point, point count, floatBitsToInt(1)).
  const gpu::Buffer& items() const { return items_; }
  std::vector<ivec4> downloadItems(size_t count) const;

 private:
  // Tests one level's `entries` queue entries (the pairs' roots at the first level), the state
  // words starting from `state`; reads them back into `state`.
  void dispatchLevel(size_t entries, bool first_level, uint32_t* state);
  // Makes `buffer` hold at least `count` elements of `bytes` (a quarter more when it grows).
  static void reserve(gpu::Buffer& buffer, size_t& capacity, size_t count, size_t bytes);

  const PointStore& store_;
  gpu::Program program_;
  gpu::Buffer nodes_, roots_, c3rcs_, state_, items_, queue_in_, queue_out_;
  size_t item_capacity_ = 0, in_capacity_ = 0, out_capacity_ = 0;  // elements they hold
  std::vector<C3rcData> local_;  // [c3rc * clouds + cloud]: object space
};

}  // namespace mirage
