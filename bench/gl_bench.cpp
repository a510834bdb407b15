// The GPU side of the envmap baseline on the headless context: one reflection-probe capture
// (six faces through the shared passes, as the envmap method's first pass draws them) and the
// envmap method's first frame (every probe captured, order 2) against its steady frames (no
// capture), at face sizes 128/256/512. Timed with the wall clock around glFinish(): on
// llvmpipe GL timer queries measure command submission, not rendering.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/error.h"
#include "gpu/context.h"
#include "gpu/program.h"
#include "methods/frame.h"
#include "render/base_colour.h"
#include "render/cube_capture.h"
#include "render/frame_target.h"
#include "scene/builtin_scenes.h"

namespace mirage::bench {

namespace {

constexpr int kFaceSizes[] = {128, 256, 512};

// spheres9 on the GPU at the benchmark size; created on first use (GL objects need the
// context, which outlives them: it is created first, so destroyed last).
struct GlScene {
  Scene scene = makeBuiltinScene("spheres9");
  FrameRenderer renderer{scene, kSize};
  View view{scene.camera(), kSize};
  FrameSettings settings{2, true};
  gpu::Program base = baseColourProgram();
};

GlScene& glScene() {
  static GlScene s;
  return s;
}

void captureProbe(benchmark::State& state, int size) {
  GlScene& s = glScene();
  const int reflector = s.scene.reflectorInstances().front();
  CubeCapture capture(size);
  gpu::Texture target = gpu::Texture::createCubeArray(GL_RGBA16F, size, 1);
  const vec3 center = s.renderer.gpu().instanceBounds(reflector).center();
  const float radius = std::max(s.scene.bounds().radius(), 1e-3f);
  auto run = [&] {
    capture.capture(target, 0, center, 1e-3f * radius, 100.0f * radius, [&](const View& v) {
      s.renderer.passes().begin(v, s.settings);
      s.renderer.passes().drawDirect();
      s.renderer.passes().drawReflectors(s.base, reflector);
    });
    glFinish();
  };
  run();  // the driver compiles shader variants on first use: keep that out of the figure
  for (auto _ : state) run();
  state.SetItemsProcessed(int64_t(state.iterations()) * 6);  // faces
  state.counters["face_size"] = size;
}

void envmapFrame(benchmark::State& state, int size, bool first) {
  GlScene& s = glScene();
  const std::map<std::string, std::string> params = {{"envmap-size", std::to_string(size)}};
  auto frame = [&](Method& method) {
    s.renderer.render(method, s.view, 0.0f, s.settings);
    glFinish();
  };
  std::unique_ptr<Method> method = s.renderer.createMethod("envmap", params, s.settings);
  frame(*method);  // compiles the driver's shader variants
  for (auto _ : state) {
    if (first) {
      state.PauseTiming();
      method = s.renderer.createMethod("envmap", params, s.settings);
      glFinish();
      state.ResumeTiming();
    }
    frame(*method);
  }
  state.counters["face_size"] = size;
  state.counters["cube_captures"] = method->stats()["cube_captures"];
}

// What the raytrace method does with the tracer's image each frame: FrameTarget::upload (copy,
// flip to GL's bottom-up rows, upload colour and ids), then glFinish.
void uploadTracedFrame(benchmark::State& state, ivec2 size) {
  FrameTarget target(size);
  Image color(size.x, size.y, vec4(0.5f));
  IdImage ids(size.x, size.y, 1u);
  target.upload(color, ids);
  glFinish();
  for (auto _ : state) {
    target.upload(color, ids);
    glFinish();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * size.x * size.y);  // pixels
}

// A whole frame of the `raytrace` method as `mirage bench` times it (tracer, upload of colour
// and ids, glFinish), to set beside render/... (the tracer alone).
void raytraceMethodFrame(benchmark::State& state) {
  GlScene& s = glScene();
  std::unique_ptr<Method> method = s.renderer.createMethod("raytrace", {}, s.settings);
  auto frame = [&] {
    s.renderer.render(*method, s.view, 0.0f, s.settings);
    glFinish();
  };
  frame();  // builds the BVH
  for (auto _ : state) frame();
  state.counters["trace_ms"] = method->stats()["trace_ms"] / double(state.iterations() + 1);
}

}  // namespace

void registerGlBenchmarks() {
  static std::unique_ptr<gpu::Context> context;
  try {
    context = gpu::createHeadlessContext();
  } catch (const Error& e) {
    noteSkipped("gl", std::string("no OpenGL 4.5 context: ") + e.what());
    return;
  }
  benchmark::AddCustomContext("gl_renderer", context->info().renderer);
  benchmark::RegisterBenchmark("gl/raytrace_method_frame/spheres9", raytraceMethodFrame)
      ->Apply(rayBenchmark);
  for (ivec2 size : {kSize, ivec2(1280, 960)}) {
    std::string name = "gl/frame_target_upload/";
    name += std::to_string(size.x) + "x" + std::to_string(size.y);
    benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
      uploadTracedFrame(state, size);
    })->Apply(rayBenchmark);
  }
  for (int size : kFaceSizes) {
    std::string suffix = "/";  // (GCC 12 warns, wrongly, on "literal" + std::string here)
    suffix += std::to_string(size);
    benchmark::RegisterBenchmark(("gl/cube_capture/spheres9" + suffix).c_str(),
                                 [=](benchmark::State& state) { captureProbe(state, size); })
        ->Apply(rayBenchmark);
    benchmark::RegisterBenchmark(("gl/envmap_first_frame/spheres9" + suffix).c_str(),
                                 [=](benchmark::State& state) { envmapFrame(state, size, true); })
        ->Apply(rayBenchmark);
    benchmark::RegisterBenchmark(("gl/envmap_steady_frame/spheres9" + suffix).c_str(),
                                 [=](benchmark::State& state) { envmapFrame(state, size, false); })
        ->Apply(rayBenchmark);
  }
}

}  // namespace mirage::bench
