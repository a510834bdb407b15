// mirage_microbench: Google Benchmark micro-benchmarks of the ray tracer, Embree, the
// environment lookups and the cube-map captures (docs/benchmarks.md). scripts/microbench
// builds and runs it with JSON output.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "bench_registry.h"
#include "bench_scenes.h"

namespace mirage::bench {

void rayBenchmark(benchmark::internal::Benchmark* b) {
  b->UseRealTime()
      ->Unit(benchmark::kMillisecond)
      ->ComputeStatistics("min", [](const std::vector<double>& v) {
        return *std::min_element(v.begin(), v.end());
      });
}

void noteSkipped(const std::string& what, const std::string& why) {
  std::fprintf(stderr, "mirage_microbench: skipping %s: %s\n", what.c_str(), why.c_str());
  benchmark::AddCustomContext("skipped " + what, why);
}

namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

void addContext() {
  benchmark::AddCustomContext("cpu_model", cpuModel());
  benchmark::AddCustomContext("tbb_threads", std::to_string(hardwareThreads()));
  RTCDevice device = rtcNewDevice(std::getenv("MIRAGE_EMBREE_CONFIG"));
  std::string packets;
  for (auto [width, property] : {std::pair{4, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED},
                                 {8, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED},
                                 {16, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED}})
    if (rtcGetDeviceProperty(device, property)) {
      if (!packets.empty()) packets += ',';
      packets += std::to_string(width);
    }
  benchmark::AddCustomContext(
      "embree_version", std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION)));
  benchmark::AddCustomContext("embree_native_packets", packets.empty() ? "none" : packets);
  rtcReleaseDevice(device);
}

}  // namespace
}  // namespace mirage::bench

int main(int argc, char** argv) {
  // The tracer's progress bar would interleave with the benchmark table.
  setenv("MIRAGE_NO_PROGRESS", "1", 0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  using namespace mirage::bench;
  addContext();
  registerEmbreeBenchmarks();
  registerFrameBenchmarks();
  registerEnvironmentBenchmarks();
  registerGlBenchmarks();
  registerSrdmBenchmarks();
  registerHybridBenchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
