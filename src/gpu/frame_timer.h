// Times the parts of a frame (update: captures and builds; direct: the scene without
// reflections; reflect: the reflections). Two clocks (docs/architecture.md, "Timing"):
//  - wall: glFinish() at each part boundary and the steady clock. Required on llvmpipe, whose
//    timer queries measure command submission, not rasterisation;
//  - gpu: GL_TIMESTAMP queries at each boundary, no stalls, for real GPUs: a frame's queries
//    are read once the GPU has answered them (looked at as each frame begins, never waited for)
//    and then used again, so that a long run holds the queries of the frames in flight only.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/timer.h"
#include "gpu/handle.h"

namespace mirage::gpu {

enum class Part { kUpdate = 0, kDirect = 1, kReflect = 2 };
inline constexpr int kPartCount = 3;
const char* partName(Part part);

enum class Clock { kWall, kGpu };
// The clock that measures truthfully on this context: wall for software rasterisers.
Clock defaultClock(bool software_renderer);
const char* clockName(Clock clock);

struct FrameTimes {
  double total_ms = 0.0;
  std::array<double, kPartCount> part_ms{};  // parts not entered stay 0
};

class FrameTimer {
 public:
  explicit FrameTimer(Clock clock) : clock_(clock) {}
  Clock clock() const { return clock_; }

  void beginFrame();
  // Ends the current part (if any) and starts `part`.
  void beginPart(Part part);
  // Ends the frame. With the wall clock the times are known at once.
  void endFrame();
  // Moves `ms` of the current frame's time from part `from` to part `to`: for CPU work that
  // measures its own split (the ray tracer's primary and reflected rays run interleaved).
  void shift(Part from, Part to, double ms);
  // All finished frames, oldest first (resolves pending GPU queries, stalling if needed).
  std::vector<FrameTimes> takeResults();

 private:
  struct Mark {
    int part;  // -1: frame start, kPartCount: frame end
    double wall_ms;
    GLuint query;
  };
  void mark(int part);

  Clock clock_;
  Stopwatch stopwatch_;
  struct Frame {
    std::vector<Mark> marks;
    std::array<double, kPartCount> shift_ms{};
  };
  // The frame's times from its marks (the GPU's answers must be in).
  FrameTimes resolve(const Frame& frame) const;
  // Resolves the pending frames whose queries the GPU has answered, oldest first; all of them
  // (waiting) with `wait`. Their queries go back to the free list.
  void harvest(bool wait);
  Frame current_;
  std::vector<Frame> pending_;                // ended, not resolved yet (GPU clock)
  std::vector<FrameTimes> done_;              // resolved, not taken yet
  std::vector<Handle<QueryTraits>> queries_;  // every query made, owned
  std::vector<GLuint> free_;                  // those no frame uses now
};

}  // namespace mirage::gpu
