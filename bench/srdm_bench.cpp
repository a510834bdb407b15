// The SRDM builder (the impostor paper, §4.1-4.2; its §5.1 table: 210 / 300 / 480 / 980 ms for
// m = 8 / 16 / 32 / 64 at w = 256, n = 60): the multithreaded CPU builder on a depth map of a
// built-in object (spheres9's teapot) and, when the asset package is fetched, of the Stanford
// bunny, ray-traced through the depth-map camera; and the GPU builder (srdm/build-gpu/...) on the
// same maps as textures, timed with the wall clock around glFinish (on llvmpipe GL timer queries
// measure submission), skipped with a message without OpenGL 4.5.
#include <benchmark/benchmark.h>
#include <epoxy/egl.h>

#include <cstring>
#include <map>
#include <memory>

#include "bench_registry.h"
#include "core/error.h"
#include "gpu/context.h"
#include "support/depth_camera.h"
#include "methods/depthmap/srdm.h"
#include "methods/depthmap/srdm_gpu_builder.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loader.h"

namespace mirage::bench {

namespace {

// A w x w depth map of the first instance named `name` in `scene`, seen from the front (+z)
// with the paper's narrow camera.
DepthMap objectDepthMap(const Scene& scene, const std::string& name, int size) {
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    if (scene.instances[i].name != name) continue;
    const Bounds3 b = scene.instanceBounds(int(i));
    const View camera = depthCamera(b.center(), b.radius(), vec3(0.3f, 0.2f, 1.0f), 30.0f, size);
    return traceDepthMap(scene, int(i), 0.0f, camera);
  }
  throwRuntime("no instance '{}' in scene '{}'", name, scene.name);
}

// The maps, built (or found missing, with the reason) on first use and kept for the process.
struct NamedMap {
  DepthMap map;
  std::string missing;  // why there is no map: the bunny's assets are not fetched
};
const NamedMap& depthMapNamed(const std::string& which) {
  static std::map<std::string, NamedMap> maps;
  auto [it, added] = maps.try_emplace(which);
  if (!added) return it->second;
  if (which == "teapot") {
    it->second.map = objectDepthMap(makeBuiltinScene("spheres9"), "teapot", 256);
    return it->second;
  }
  try {
    it->second.map = objectDepthMap(loadScene("bunny"), "bunny", 256);
  } catch (const Error& e) {
    it->second.missing = e.what();
  }
  return it->second;
}

void buildSrdms(benchmark::State& state, const std::string& which, SrdmSimplifier simplifier) {
  const NamedMap& named = depthMapNamed(which);
  if (!named.missing.empty()) {
    state.SkipWithError(named.missing.c_str());
    return;
  }
  const DepthMap* map = &named.map;
  const SrdmSettings settings{int(state.range(0)), int(state.range(1)), simplifier};
  Srdm srdm;
  for (auto _ : state) {
    srdm = buildSrdm(*map, settings);
    benchmark::DoNotOptimize(srdm.texels.data());
  }
  const SrdmError error = measureSrdmError(*map, srdm);
  state.counters["n"] = settings.domains;
  state.counters["m"] = settings.points;
  state.counters["kB"] = double(srdm.bytes()) / 1024.0;
  state.counters["rel_z_error_pct"] = 100.0 * error.mean;
  state.counters["dropped_pct"] =
      100.0 * double(error.dropped) / double(std::max(error.samples + error.dropped, 1L));
}

// The GPU builder and the maps as textures, created on first use; the context (gl_bench's, or
// our own when there is none) outlives them.
struct GpuState {
  std::unique_ptr<gpu::Context> own_context;
  std::unique_ptr<SrdmGpuBuilder> builder;
  std::map<std::string, gpu::Texture> depth;
};
GpuState& gpuState() {
  static GpuState s;
  return s;
}

void buildSrdmsOnGpu(benchmark::State& state, const std::string& which) {
  const NamedMap& named = depthMapNamed(which);
  if (!named.missing.empty()) {
    state.SkipWithError(named.missing.c_str());
    return;
  }
  const DepthMap& map = named.map;
  GpuState& gpu = gpuState();
  if (!gpu.builder) gpu.builder = std::make_unique<SrdmGpuBuilder>();
  auto [it, added] = gpu.depth.try_emplace(which);
  if (added) it->second = uploadDepthMap(map);
  const SrdmSettings settings{int(state.range(0)), int(state.range(1)), SrdmSimplifier::kGreedy};
  gpu::Texture out = SrdmGpuBuilder::createOutput(map.size, settings);
  auto run = [&] {
    gpu.builder->build(it->second, map.near, map.far, settings, out);
    glFinish();
  };
  run();  // compiles the row program for this m (and the driver's variant): kept out
  for (auto _ : state) run();
  const Srdm srdm = gpu.builder->download(out, settings.points);
  const Srdm cpu = buildSrdm(map, settings);
  long differing = 0;
  const size_t row_bytes = size_t(srdm.pairs()) * sizeof(vec4);
  for (size_t r = 0; r < size_t(srdm.domains) * size_t(srdm.size); ++r)
    differing += std::memcmp(&srdm.texels[r * size_t(srdm.pairs())],
                             &cpu.texels[r * size_t(cpu.pairs())], row_bytes) != 0;
  const SrdmError error = measureSrdmError(map, srdm);
  state.counters["n"] = settings.domains;
  state.counters["m"] = settings.points;
  state.counters["kB"] = double(srdm.bytes()) / 1024.0;
  state.counters["rel_z_error_pct"] = 100.0 * error.mean;
  state.counters["rows_unlike_cpu"] = double(differing);
}

}  // namespace

void registerSrdmBenchmarks() {
  for (const char* which : {"teapot", "bunny"})
    for (SrdmSimplifier simplifier : {SrdmSimplifier::kGreedy, SrdmSimplifier::kFit}) {
      const std::string name =
          std::string("srdm/build/") + which + "/" + srdmSimplifierName(simplifier);
      benchmark::RegisterBenchmark(
          name.c_str(),
          [which, simplifier](benchmark::State& state) { buildSrdms(state, which, simplifier); })
          ->ArgNames({"n", "m"})
          ->Args({60, 8})
          ->Args({60, 10})
          ->Args({60, 12})
          ->Args({60, 14})
          ->Args({60, 16})
          ->Args({60, 32})
          ->Args({60, 64})
          ->Args({18, 8})
          ->Apply(rayBenchmark);
    }
  // The GPU builder needs a current context: gl_bench's when it made one, else our own.
  if (eglGetCurrentContext() == EGL_NO_CONTEXT) {
    try {
      gpuState().own_context = gpu::createHeadlessContext();
    } catch (const Error& e) {
      noteSkipped("srdm/build-gpu", std::string("no OpenGL 4.5 context: ") + e.what());
      return;
    }
  }
  for (const char* which : {"teapot", "bunny"})
    benchmark::RegisterBenchmark(
        (std::string("srdm/build-gpu/") + which + "/greedy").c_str(),
        [which](benchmark::State& state) { buildSrdmsOnGpu(state, which); })
        ->ArgNames({"n", "m"})
        ->Args({60, 8})
        ->Args({60, 16})
        ->Args({60, 32})
        ->Args({60, 64})
        ->Args({18, 8})
        ->Apply(rayBenchmark);
}

}  // namespace mirage::bench
