// The groups of micro-benchmarks mirage_microbench registers (one file each) and the settings
// they share.
#pragma once

#include <benchmark/benchmark.h>

#include <string>

namespace mirage::bench {

// Wall-clock time (the work runs on TBB threads, or on the GPU driver's), in milliseconds,
// with a `min` statistic next to mean/median/stddev when --benchmark_repetitions is given:
// on a shared machine the minimum is the figure least disturbed by other load.
void rayBenchmark(benchmark::internal::Benchmark* b);

void registerEmbreeBenchmarks();
void registerFrameBenchmarks();  // RayTracer::render frames, BVH builds
void registerEnvironmentBenchmarks();
void registerGlBenchmarks();      // cube-map captures; skipped with a message without OpenGL 4.5
void registerSrdmBenchmarks();    // the CPU and GPU SRDM builders (w = 256, n and m as the paper)
void registerHybridBenchmarks();  // the hybrid method's kd-tree build (the paper's six counts)

// Records a benchmark group that could not run and why (in the JSON context and on stderr).
void noteSkipped(const std::string& what, const std::string& why);

}  // namespace mirage::bench
