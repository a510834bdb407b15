// The frame timer (gpu/frame_timer.h): with the GPU clock a long run holds the queries of the
// frames in flight only (each frame's are read once the GPU answered them and then used again),
// and every frame's times come back, in order, whole.
#include <gtest/gtest.h>

#include "gpu/frame_timer.h"
#include "gpu/gl.h"
#include "gpu/object_count.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

class FrameTimerGpu : public GlTest {};

TEST_F(FrameTimerGpu, ALongRunReusesItsQueries) {
  gpu::FrameTimer timer(gpu::Clock::kGpu);
  const long before = gpu::liveHandles().queries;
  constexpr int kFrames = 300;
  for (int f = 0; f < kFrames; ++f) {
    timer.beginFrame();
    timer.beginPart(gpu::Part::kDirect);
    glClear(GL_COLOR_BUFFER_BIT);
    timer.beginPart(gpu::Part::kReflect);
    glClear(GL_COLOR_BUFFER_BIT);
    timer.endFrame();
    // The GPU done with the frame: its queries are answered by the next frame's start (how many
    // frames stay in flight otherwise depends on the driver and the machine's load).
    glFinish();
  }
  // Four queries a frame, for the frame being answered and the next; without reuse, 1,200.
  EXPECT_LE(gpu::liveHandles().queries - before, 4 * 2);
  const std::vector<gpu::FrameTimes> times = timer.takeResults();
  ASSERT_EQ(times.size(), size_t(kFrames));
  for (const gpu::FrameTimes& t : times) {
    EXPECT_GE(t.total_ms, 0.0);
    EXPECT_GE(t.part_ms[size_t(gpu::Part::kDirect)], 0.0);
    EXPECT_LE(t.part_ms[size_t(gpu::Part::kDirect)] + t.part_ms[size_t(gpu::Part::kReflect)],
              t.total_ms + 1e-9);
  }
  EXPECT_TRUE(timer.takeResults().empty());
}

}  // namespace
}  // namespace mirage::test
