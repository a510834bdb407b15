// The SRDM builder on the GPU (the impostor paper, §4.1-4.2; its §6 names a GPU builder as future
// work): the rows of buildSrdm with the greedy simplifier, built by a compute shader from a depth
// map that is already a texture (the depth-map capture's), into the RGBA32F array the
// intersection shader reads. It runs the CPU builder's arithmetic (srdm_build_shared.h) and its
// tie-breaking, so that the two agree row for row (tests/methods/srdm_gpu_builder_test.cpp).
//
// Only the greedy simplifier runs here: asking for `fit` is an InputError naming `greedy`.
#pragma once

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/depthmap/srdm.h"

namespace mirage {

class SrdmGpuBuilder {
 public:
  // Compiles the box pass (the row pass is compiled per capacity on first use): needs a current
  // OpenGL 4.5 context.
  SrdmGpuBuilder();

  // The output array for a w x w depth map: RGBA32F, (m + 1) / 2 x w texels, n layers.
  static gpu::Texture createOutput(int size, const SrdmSettings& settings);
  // The worst case of srdm_build.comp's row pass in the loop limiter's count
  // (gpu/loop_budget.h), for rows of up to `samples` samples and m points: the scan offering
  // each span, the knots, the queue's heap (worst_of's scan and a heap walk of log2 m) and the
  // refinement to m points, and the row's writes. A build beyond the loop budget is a GpuError.
  static long long rowLoopCost(int samples, int m);

  // Queues the build of `depth` (R32F or DEPTH_COMPONENT32F 2D, w x w, GL window depth of a
  // camera with planes near < far, >= 1 background) into `out` (createOutput's shape). Does not
  // wait; a memory barrier makes the result visible to later texture fetches and read-backs.
  // Throws InputError for settings out of buildSrdm's range or for the fit simplifier, and
  // RuntimeError for textures of the wrong kind.
  void build(const gpu::Texture& depth, float near, float far, const SrdmSettings& settings,
             gpu::Texture& out);

  // The samples of dropped spans in the last build (waits for it).
  int droppedSamples() const;

  // `out` read back as buildSrdm's Srdm, with the last build's dropped samples (waits).
  Srdm download(const gpu::Texture& out, int points) const;

  // Uploads `map`, builds and reads back: the GPU counterpart of buildSrdm.
  Srdm build(const DepthMap& map, const SrdmSettings& settings);

 private:
  const gpu::Program& rowProgram(int points);

  gpu::Program box_;
  gpu::Program rows_[6];  // capacities 8, 16, ..., 256 points (SRDM_MAX_POINTS)
  gpu::Buffer domains_, state_;
  int domain_count_ = 0, domain_size_ = 0;  // what domains_ holds
};

// A depth map as an R32F texture (nearest filtering), as the GPU builder reads it.
gpu::Texture uploadDepthMap(const DepthMap& map);

}  // namespace mirage
