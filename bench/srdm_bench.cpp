// The SRDM builder (the impostor paper, §4.1-4.2; its §5.1 table: 210 / 300 / 480 / 980 ms for
// m = 8 / 16 / 32 / 64 at w = 256, n = 60): the multithreaded CPU builder on a depth map of a
// built-in object (spheres9's teapot) and, when the asset package is fetched, of the Stanford
// bunny, ray-traced through the depth-map camera.
#include <benchmark/benchmark.h>

#include <map>

#include "bench_registry.h"
#include "core/error.h"
#include "methods/depthmap/depth_camera.h"
#include "methods/depthmap/srdm.h"
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
}

}  // namespace mirage::bench
