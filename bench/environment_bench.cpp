// CPU cube-map lookups (EnvironmentMap::sample): what every ray that leaves the scene costs
// the ray tracer. Bilinear, seamless across faces; face size as the scene's sky (256).
#include <benchmark/benchmark.h>

#include <random>

#include "bench_registry.h"
#include "bench_scenes.h"

namespace mirage::bench {

namespace {

// Directions spread uniformly over the sphere (fixed seed: every run looks up the same texels).
std::vector<vec3> uniformDirections(size_t count) {
  std::mt19937 random(12345);
  std::normal_distribution<float> normal;
  std::vector<vec3> directions(count);
  for (vec3& d : directions) {
    do d = vec3(normal(random), normal(random), normal(random));
    while (glm::dot(d, d) < 1e-6f);
    d = glm::normalize(d);
  }
  return directions;
}

void sampleEnvironment(benchmark::State& state, const EnvironmentMap& env,
                       const std::vector<vec3>& directions) {
  for (auto _ : state) {
    vec3 sum(0.0f);
    for (const vec3& d : directions) sum += env.sample(d);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(directions.size()));
  state.counters["face_size"] = env.faceSize();
}

}  // namespace

void registerEnvironmentBenchmarks() {
  benchmark::RegisterBenchmark("environment/sample/uniform", [](benchmark::State& state) {
    static const std::vector<vec3> directions = uniformDirections(1 << 20);
    sampleEnvironment(state, benchScene("spheres9").environment, directions);
  })->Apply(rayBenchmark);
  // The directions the ray tracer really looks up: reflected rays, most of which leave spheres9.
  benchmark::RegisterBenchmark("environment/sample/reflected-spheres9",
                               [](benchmark::State& state) {
                                 const BenchScene& b = benchScene("spheres9");
                                 static const std::vector<vec3> directions = [&] {
                                   std::vector<vec3> d;
                                   for (const Ray& r : b.reflected) d.push_back(r.direction);
                                   return d;
                                 }();
                                 sampleEnvironment(state, b.environment, directions);
                               })
      ->Apply(rayBenchmark);
}

}  // namespace mirage::bench
