// The loop limiter's count that gpu/loop_budget.h plans with, measured on the driver the tests
// run on: on llvmpipe every loop of an invocation draws from one counter of 65,535 (an
// iteration, or the test that leaves a loop, one each), nested and sequential loops alike, and a
// divergent batch pays for its longest lane; a driver without a limiter runs every loop in full.
// The budget stays below the limit measured.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/loop_budget.h"
#include "gpu/program.h"
#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::gpu {
namespace {

static_assert(loopCost(0) == 1 && loopCost(3) == 4 && loopCost(2, loopCost(5)) == 15);
static_assert(kShaderLoopBudget < kDriverLoopLimit);

// Lane 0 of each batch of 8 runs `u_outer` x `u_inner` nested iterations, then `u_after`
// more in a second loop; the other lanes run one outer iteration (u_diverge = 1) or the same.
constexpr const char* kProbe = R"(layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Out { uint counts[]; };
uniform int u_outer, u_inner, u_after, u_diverge;
void main() {
  uint lane = gl_LocalInvocationID.x;
  int outer = (u_diverge != 0 && lane != 0u) ? 1 : u_outer;
  uint nested = 0u, after = 0u;
  for (int i = 0; i < outer; ++i)
    for (int j = 0; j < u_inner; ++j) nested += 1u;
  for (int i = 0; i < u_after; ++i) after += 1u;
  counts[2u * lane] = nested;
  counts[2u * lane + 1u] = after;
}
)";

class DriverLoopLimit : public test::GlTest {
 protected:
  struct Counts {
    uint32_t nested, after;
  };
  // Lane 0's counts.
  Counts run(int outer, int inner, int after, bool diverge) {
    if (!program_) {
      dir_.write("render/shaders/fullscreen.vert", kProbe);  // any embedded path serves
      program_ = Program::compute("render/shaders/fullscreen.vert");
    }
    Buffer out(16 * sizeof(uint32_t));
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    program_.set("u_outer", outer);
    program_.set("u_inner", inner);
    program_.set("u_after", after);
    program_.set("u_diverge", diverge ? 1 : 0);
    program_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    uint32_t v[16];
    out.download(v, sizeof(v));
    return {v[0], v[1]};
  }
  bool limited() const { return currentContextIsSoftware(); }

  test::ScopedShaderDir dir_{"loop-limit"};
  Program program_;
};

TEST_F(DriverLoopLimit, NestedLoopsDrawFromOneCounter) {
  // 642 x 100 nested: 642 (1 + 101) + 1 = 65,485, within the limit; 643 x 100 is 65,587.
  ASSERT_EQ(loopCost(642, loopCost(100)), 65485);
  EXPECT_EQ(run(642, 100, 0, false).nested, 64200u) << "within the limit: run in full";
  const Counts over = run(643, 100, 0, false);
  if (limited())
    EXPECT_LT(over.nested, 64300u) << "llvmpipe cuts a nest beyond 65,535 in its count";
  else
    EXPECT_EQ(over.nested, 64300u);
}

TEST_F(DriverLoopLimit, SequentialLoopsShareTheCounter) {
  // 300 x 100 nested (30,601) then 34,900 more (34,901): 65,502 in all, within; 35,100: over.
  EXPECT_EQ(run(300, 100, 34900, false).after, 34900u);
  const Counts over = run(300, 100, 35100, false);
  EXPECT_EQ(over.nested, 30000u);
  if (limited())
    EXPECT_LT(over.after, 35100u) << "the second loop pays for the first";
  else
    EXPECT_EQ(over.after, 35100u);
}

TEST_F(DriverLoopLimit, ADivergentBatchPaysForItsLongestLane) {
  // One lane's 643 x 100 is over the limit though the other seven run one outer iteration.
  const Counts over = run(643, 100, 0, true);
  if (limited())
    EXPECT_LT(over.nested, 64300u);
  else
    EXPECT_EQ(over.nested, 64300u);
  EXPECT_EQ(run(642, 100, 0, true).nested, 64200u);
}

}  // namespace
}  // namespace mirage::gpu
