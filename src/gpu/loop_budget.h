// What the loops of one shader invocation may cost (docs/architecture.md, "Shader loops").
//
// llvmpipe ends every loop of an invocation once their iterations together reach 65,535
// (gallivm's loop limiter, LP_MAX_TGSI_LOOP_ITERATIONS): one counter for the whole invocation
// (a SIMD batch of lanes, run while any lane is active), which each iteration of any loop and
// each test that leaves a loop draws one from, nested and sequential loops alike. The loop is cut
// without a word and the shader goes on after it. The tests measure that model on the driver
// they run on (DriverLoopLimit.*). Every shader of mirage that loops over data has its worst
// case in this count written beside it on the host, and the host keeps it within
// kShaderLoopBudget, by how it splits the work (the splatting pass's runs) or by checking the
// data before the draw (a driver limit: GpuError, the fallback).
#pragma once

#include <string>

#include "core/error.h"

namespace mirage::gpu {

// llvmpipe's limit, and what mirage's shaders plan for: a sixteenth below it.
inline constexpr long long kDriverLoopLimit = 65535;
inline constexpr long long kShaderLoopBudget = 61440;

// The cost of a loop that runs `trips` times with a body costing `body` each time: each
// iteration, what its body's loops cost, and the test that leaves.
constexpr long long loopCost(long long trips, long long body = 0) {
  return trips * (1 + body) + 1;
}

// Throws a GpuError (a driver limit: the method falls back) naming the pass, when its worst case
// `cost` is beyond the budget.
inline void checkLoopBudget(const std::string& pass, long long cost) {
  if (cost > kShaderLoopBudget)
    throwGpu(
        "{}: a shader invocation's loops could run {} iterations, beyond the {} mirage plans for "
        "under software rasterisers' loop limit ({}; docs/architecture.md, \"Shader loops\")",
        pass, cost, kShaderLoopBudget, kDriverLoopLimit);
}

}  // namespace mirage::gpu
