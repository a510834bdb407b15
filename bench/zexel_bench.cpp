// The zexel method's CPU warper (the forward-mapped planar mirror paper, §4.1: 15 fps on 4 CPUs
// against 10 on one): a 512² map — a wall behind two spheres, ray-cast — warped into a 640x480
// mirrored view, every zexel of the full map (the hierarchy off: tiles at level 0), on 1 and 2
// threads, with 1x1 and 3x3 splats. Zexels per second are the items.
#include <benchmark/benchmark.h>

#include <cmath>

#include <tbb/task_arena.h>

#include "bench_registry.h"
#include "methods/zexel/zexel_camera.h"
#include "methods/zexel/zexel_cpu_warper.h"

namespace mirage::bench {

namespace {

struct WarpCase {
  ZexelMap2D map;
  std::vector<ZexelMap2D> levels;
  WarpCamera in, out;
  ivec2 size{640, 480};
};

const WarpCase& warpCase() {
  static const WarpCase c = [] {
    const vec3 mirror(0.0f, 1.0f, -2.0f), normal(0.0f, 0.0f, 1.0f);
    const int n = 512;
    const View reference = zexelReferenceView(mirror, normal, 1.2f, n, 100.0f);
    WarpCase w;
    w.in = {zexelPixelMatrix(reference, reference.nearPlane()), reference.eye()};
    CameraDesc eye;
    eye.position = {1.2f, 1.5f, 3.0f};
    eye.target = mirror;
    const View output = View(eye, w.size).mirrored(mirror, normal);
    w.out = {zexelPixelMatrix(output, output.nearPlane()), output.eye()};
    w.map.width = w.map.height = n;
    w.map.texels.resize(size_t(n) * size_t(n));
    const vec4 spheres[2] = {{0.0f, 1.0f, -1.0f, 0.4f}, {0.5f, 1.2f, -0.3f, 0.2f}};
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const vec3 d = glm::normalize(w.in.p * vec3(float(x) + 0.5f, float(y) + 0.5f, 1.0f));
        float t = (2.0f - w.in.c.z) / d.z;  // the wall z = 2
        for (const vec4& s : spheres) {
          const vec3 oc = w.in.c - vec3(s);
          const float b = glm::dot(oc, d), disc = b * b - glm::dot(oc, oc) + s.w * s.w;
          if (disc >= 0.0f && -b - std::sqrt(disc) > 0.0f) t = std::min(t, -b - std::sqrt(disc));
        }
        w.map.texels[size_t(y) * size_t(n) + size_t(x)] = vec4(vec3(0.5f), t);
      }
    w.levels = zexelPyramid(w.map);
    return w;
  }();
  return c;
}

void warpCpu(benchmark::State& state) {
  const WarpCase& c = warpCase();
  const int threads = int(state.range(0));
  ZexelSplatOptions o;
  o.splat = int(state.range(1));
  o.rect = ivec4(0, 0, c.size);
  o.tile_level = 3;
  o.lod = false;
  const std::vector<ZexelWarpSource> sources = {
      {c.levels.data(), int(c.levels.size()), c.map.width, c.in}};
  tbb::task_arena arena(threads);
  for (auto _ : state)
    arena.execute([&] { benchmark::DoNotOptimize(warpZexels(sources, c.out, o, threads > 1)); });
  state.SetItemsProcessed(state.iterations() * int64_t(c.map.texels.size()));
}

}  // namespace

BENCHMARK(warpCpu)
    ->ArgNames({"threads", "splat"})
    ->ArgsProduct({{1, 2}, {1, 3}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace mirage::bench
