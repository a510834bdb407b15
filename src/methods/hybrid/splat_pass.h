// The forward phase's splatting pass (the hybrid paper, §6; hybrid_splat.comp): every work item's
// points projected through its C3RC and splatted, a workgroup per run of consecutive items
// (itemRuns), then the per-pixel visibility's second pass (splat_visibility.h). The pass owns its
// program, its buffers and the counters the shader adds into.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "methods/hybrid/c3rc.h"
#include "methods/hybrid/c3rc_frame.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/point_store.h"
#include "methods/hybrid/splat_visibility.h"
#include "methods/method.h"

namespace mirage {

struct SplatSettings {
  bool first_only = false;      // the first projection within a C3RC only
  bool keep_backfaces = false;  // project the back-facing points of closed objects too
  int splat_size = 0;           // frame pixels a side; 0: from the point spacing
  int pixel_scale = 1;          // frame pixels per output pixel along a side (--ssaa)
};

// The items to splat: on the CPU (uploaded, and grouped into runs), or already on the GPU
// (`count` of them, each of at most `gpu_points` points: cut into slices of a run each).
struct SplatItems {
  const std::vector<ivec4>* cpu = nullptr;
  const gpu::Buffer* gpu = nullptr;
  size_t count = 0;
  long long gpu_points = 0;
};

class SplatPass {
 public:
  explicit SplatPass(const SplatSettings& settings);

  // Splats `items` (C3RCs `c3rcs`, world space) into the frame's visibility words; the resolve
  // pass reads the winners. `reflector_ids`: the frame's triangle-ID image (instance + 1,
  // primitive), where a splat lands only on its own reflector's pixels. Times itself when the
  // frame is timed.
  // With `count_only`, splats nothing and counts each item's taken points with a projection
  // (seenPerItem): the level of detail's probe.
  void run(FrameContext& frame, PointStore& store, const std::vector<C3rcData>& c3rcs,
           const gpu::Texture& reflector_ids, const SplatItems& items, bool count_only = false);
  // The counts of the last count-only run, one per item (waits for it).
  std::vector<uint32_t> seenPerItem(size_t items) const;

  // The shader's counters of the last run (MIRAGE_HYBRID_COUNTERS: pairs given, projections,
  // splats, pairs projecting, pairs facing away, candidates).
  uint32_t counter(int i) const { return counters_[i]; }
  double ms() const { return ms_; }

  // The worst case of one point in the shader's loops, in the loop limiter's count
  // (gpu/loop_budget.h): the C3RC's hull planes, the cubic's three pieces of up to
  // MIRAGE_C3RC_ROOT_STEPS steps each, and up to three splats (one with the first projection
  // only) of the largest side squared pixels.
  static long long pointCost(const SplatSettings& settings);
  // What a run may hold on this context (one item a run on a GPU).
  RunLimits runLimits() const;
  // The points of one slice of an item on the GPU: the most a run's share of one item may take.
  long long slicePoints() const;

 private:
  std::vector<SplatRun> runs(const SplatItems& items) const;
  void dispatch(size_t run_count);

  SplatSettings settings_;
  gpu::Program program_;
  size_t run_items_;  // the most work items a run takes
  SplatVisibility visibility_;
  gpu::Buffer c3rc_buffer_, item_buffer_, run_buffer_, counter_buffer_, seen_buffer_;
  uint32_t counters_[MIRAGE_HYBRID_COUNTERS] = {};
  double ms_ = 0.0;
};

}  // namespace mirage
