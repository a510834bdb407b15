// The hybrid method's kd-tree build (the hybrid paper's Table 1: 577 / 533 / 190 / 95 / 25 / 6 ms
// for its six point sets): the eight-way TBB build over the teapot-dragon scene's dragon sampled
// to the paper's counts (0 = its 437,645 vertices), when the asset package is fetched; and over
// the built-in teapot-sphere's objects, which need no download.
#include <benchmark/benchmark.h>

#include <map>
#include <utility>

#include "bench_registry.h"
#include "core/error.h"
#include "methods/hybrid/kd_tree.h"
#include "methods/hybrid/point_set.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loader.h"

namespace mirage::bench {

namespace {

// The scenes, loaded (or found missing, with the reason) on first use and kept.
struct NamedScene {
  Scene scene;
  std::string missing;
};
const NamedScene& sceneNamed(const std::string& name) {
  static std::map<std::string, NamedScene> scenes;
  auto [it, added] = scenes.try_emplace(name);
  if (!added) return it->second;
  try {
    it->second.scene = isBuiltinScene(name) ? makeBuiltinScene(name) : loadScene(name);
  } catch (const Error& e) {
    it->second.missing = e.what();
  }
  return it->second;
}

void buildKdTree(benchmark::State& state, const std::string& scene_name) {
  const NamedScene& named = sceneNamed(scene_name);
  if (!named.missing.empty()) {
    state.SkipWithError(named.missing.c_str());
    return;
  }
  PointSetOptions options;
  options.total = state.range(0);
  std::vector<PointSet> sets =
      samplePoints(named.scene, pointSampledInstances(named.scene), options);
  std::vector<vec3> positions;
  for (const PointSet& s : sets)
    positions.insert(positions.end(), s.positions.begin(), s.positions.end());
  KdTreeStats stats;
  for (auto _ : state) {
    std::vector<uint32_t> order;
    KdTree tree(positions, KdTreeOptions{}, order);
    stats = tree.stats();
    benchmark::DoNotOptimize(order.data());
  }
  state.counters["points"] = double(positions.size());
  state.counters["leaves"] = double(stats.leaves);
  state.counters["average_depth"] = stats.average_leaf_depth;
  state.counters["points_per_leaf"] = stats.points_per_leaf;
}

}  // namespace

void registerHybridBenchmarks() {
  benchmark::RegisterBenchmark("hybrid/kd-build/teapot-dragon",
                               [](benchmark::State& s) { buildKdTree(s, "teapot-dragon"); })
      ->ArgNames({"points"})
      ->Args({543652})
      ->Args({0})
      ->Args({147000})
      ->Args({100250})
      ->Args({37000})
      ->Args({10000})
      ->Apply(rayBenchmark);
  benchmark::RegisterBenchmark("hybrid/kd-build/teapot-sphere",
                               [](benchmark::State& s) { buildKdTree(s, "teapot-sphere"); })
      ->ArgNames({"points"})
      ->Args({437645})
      ->Args({100000})
      ->Apply(rayBenchmark);
}

}  // namespace mirage::bench
