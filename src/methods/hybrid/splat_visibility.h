// The hybrid method's per-pixel visibility (hybrid_shared.h): the nearest splat's depth key per
// pixel, the candidates the splatting pass appends, and the second pass (hybrid_winner.comp) that
// leaves each pixel the lowest point index among its candidates at the final depth.
#pragma once

#include <cstddef>

#include "gpu/buffer.h"
#include "gpu/program.h"

namespace mirage {

class SplatVisibility {
 public:
  SplatVisibility();

  // Sizes the buffers for a frame of `pixels`, leaves every pixel empty (the resolve then shows
  // the background) and binds the depth and winner words.
  void begin(size_t pixels);
  // Before each splat dispatch: clears the depth words, binds the candidate buffer; returns how
  // many candidates it holds (the splatting shader's u_candidate_capacity).
  size_t prepare();
  // After a dispatch that appended `count` candidates: true when they fitted; else the buffer
  // has grown to hold them and the splatting must run again (nothing is dropped).
  bool fitted(size_t count);
  // The second pass over the `count` candidates of the last dispatch.
  void pickWinners(size_t count);

  static void clearWords(gpu::Buffer& buffer, uint32_t value);

 private:
  gpu::Program winner_program_;
  gpu::Buffer depths_, winners_, candidates_;
  size_t pixels_ = 0;
};

}  // namespace mirage
