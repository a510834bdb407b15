// `mirage bench`: frame times of several methods, measured in one run on the same frames
// (interleaved, so that drift of the machine affects all alike), written as JSON.
#include <algorithm>
#include <cstdlib>

#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/timing_summary.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/process_memory.h"
#include "core/progress.h"
#include "core/timer.h"
#include "eval/metrics.h"
#include "gpu/memory.h"
#include "gpu/object_count.h"
#include "methods/frame.h"

namespace mirage::app {

namespace {

struct BenchArgs : RenderingArgs {
  std::string methods = "none,envmap,raytrace";
  int frames = 100;
  int warmup = 5;
  double fps = 0.0;  // > 0: the scene plays, frame i at --time + i / fps
  double raytrace_budget_s = 20.0;
  std::string json;
};

nlohmann::json orNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// What the process holds at a frame: resident memory and GL objects (mirage's handles, and the
// names GL itself reports), so that a long run shows whether anything grows (the soak check).
struct Resources {
  int frame = 0;  // timed frames done
  double rss_mib = 0.0;
  long handles = 0, gl_objects = 0;
};

Resources resourcesAt(int frame) {
  glFinish();
  // Give freed memory back first (allocators keep it otherwise): what remains is memory held.
  releaseFreeMemory();
  return {frame, residentMiB(), gpu::liveHandles().total(), gpu::glObjects().total()};
}

// Frames after which resources are recorded: 0, 1, 10, 100, 1,000, then every 1,000, and the
// last — enough points to tell a plateau from a slope.
bool isCheckpoint(int done, int frames) {
  if (done == frames || (done >= 1000 && done % 1000 == 0)) return true;
  int p = 1;
  while (p < done) p *= 10;
  return p == done;
}

struct Run {
  std::string name;
  std::unique_ptr<Method> method;
  std::unique_ptr<gpu::FrameTimer> timer;
  int frames = 0;  // frames to time
  size_t reflector_pixels = 0;
  std::map<std::string, double> counts;  // the sums of the timed frames' frameCounts
  // GPU storage the method holds: what its creation and its frames allocated and kept.
  int64_t gpu_bytes = 0;
  // The timed frames' times of each assigned part (`mixed`: one per assignment entry).
  std::vector<std::pair<std::string, std::vector<double>>> entry_ms;
};

// Calls `work` (creating or rendering r's method) and charges r with the GPU storage it left.
template <typename Work>
void charged(Run& r, Work&& work) {
  const int64_t before = gpu::allocatedBytes();
  work();
  r.gpu_bytes += gpu::allocatedBytes() - before;
}

void addPartTimes(Run& r) {
  for (const Method::PartTime& p : r.method->partTimes()) {
    auto it = std::find_if(r.entry_ms.begin(), r.entry_ms.end(),
                           [&](const auto& e) { return e.first == p.label; });
    if (it == r.entry_ms.end()) it = r.entry_ms.insert(r.entry_ms.end(), {p.label, {}});
    it->second.push_back(p.ms);
  }
}

void validate(const BenchArgs& args) {
  if (args.frames < 1 || args.frames > 1000000)
    throwInput("--frames {}: allowed 1..1000000", args.frames);
  if (args.warmup < 0 || args.warmup > 100000)
    throwInput("--warmup {}: allowed 0..100000", args.warmup);
  if (!(args.raytrace_budget_s > 0.0))
    throwInput("--raytrace-budget {}: must be > 0", args.raytrace_budget_s);
  if (!(args.fps >= 0.0 && args.fps <= 1000.0))
    throwInput("--fps {}: allowed 0..1000 (0: a still frame)", args.fps);
}

std::vector<Run> createRuns(FrameRenderer& renderer, const std::vector<std::string>& names,
                            const BenchArgs& args, const FrameSettings& settings,
                            gpu::Clock gpu_clock) {
  std::vector<Run> runs;
  for (const std::string& name : names) {
    Run r;
    r.name = name;
    charged(r, [&] { r.method = renderer.createMethod(name, args.params, settings); });
    r.timer =
        std::make_unique<gpu::FrameTimer>(r.method->info().gpu ? gpu_clock : gpu::Clock::kWall);
    r.frames = args.frames;
    runs.push_back(std::move(r));
  }
  return runs;
}

// Warm-up: first frames (captures, BVH builds, shader compilation in the driver). The CPU
// reference is then given as many timed frames as its budget affords.
void warmUp(std::vector<Run>& runs, FrameRenderer& renderer, const View& view,
            const BenchArgs& args, const FrameSettings& settings) {
  for (Run& r : runs) {
    Stopwatch first;
    for (int i = 0; i < std::max(args.warmup, 1); ++i)
      charged(r, [&] { renderer.render(*r.method, view, args.scene.time, settings); });
    glFinish();
    if (!r.method->info().gpu) {
      double per_frame_s = first.ms() / 1000.0 / double(std::max(args.warmup, 1));
      // Clamped as a double: a budget of 1e9 s affords more frames than an int holds.
      const double affordable = args.raytrace_budget_s / std::max(per_frame_s, 1e-6);
      r.frames = int(std::clamp(affordable, 3.0, double(args.frames)));
    }
    r.reflector_pixels = countNonZero(renderer.read().ids);
  }
}

// What the timed frames leave besides each method's times.
struct TimedFrames {
  std::vector<double> scene_ms;  // the playing scene's shared update, per frame
  std::vector<Resources> resources;
};

// The timed frames, interleaved across methods. A playing scene moves once per frame, before the
// methods draw it: what every method shares (transforms, deformed vertices, the light) is timed
// apart from each method's update.
TimedFrames timeFrames(std::vector<Run>& runs, FrameRenderer& renderer, const CameraDesc& camera,
                       ivec2 size, const BenchArgs& args, const FrameSettings& settings) {
  // Timed frame f's time: still at --time, or playing at --fps (the scene and the camera's path)
  // from the frame after the warm-up's, so that every timed frame shows a new time.
  auto timeOf = [&](int f) {
    return args.fps > 0.0 ? args.scene.time + float(double(f + 1) / args.fps) : args.scene.time;
  };
  size_t total = 0;
  for (const Run& r : runs) total += size_t(r.frames);
  Progress progress("bench", total);
  const View still(camera.at(args.scene.time), size);
  TimedFrames out;
  out.resources.push_back(resourcesAt(0));
  for (int f = 0; f < args.frames; ++f) {
    const float time = timeOf(f);
    if (args.fps > 0.0) {
      Stopwatch watch;
      renderer.gpu().setTime(time);
      glFinish();
      out.scene_ms.push_back(watch.ms());
    }
    const View frame_view = args.fps > 0.0 ? View(camera.at(time), size) : still;
    for (Run& r : runs) {
      if (f >= r.frames) continue;
      std::map<std::string, double> counts;
      charged(r, [&] {
        renderer.render(*r.method, frame_view, time, settings, r.timer.get(), &counts);
      });
      for (const auto& [name, n] : counts) r.counts[name] += n;
      addPartTimes(r);
      progress.advance();
    }
    if (isCheckpoint(f + 1, args.frames)) out.resources.push_back(resourcesAt(f + 1));
  }
  return out;
}

nlohmann::json summaryJson(const Summary& s) {
  return {{"min", s.min}, {"median", s.median}, {"p95", s.p95}};
}

// One method's entry: its times (whole frame and parts), counts, stats and fallback.
nlohmann::json methodEntry(Run& r, const FrameSettings& settings) {
  std::vector<gpu::FrameTimes> times = r.timer->takeResults();
  std::vector<double> total_ms;
  std::array<std::vector<double>, gpu::kPartCount> parts;
  for (const auto& t : times) {
    total_ms.push_back(t.total_ms);
    for (int p = 0; p < gpu::kPartCount; ++p) parts[size_t(p)].push_back(t.part_ms[size_t(p)]);
  }
  const Summary s = summarize(total_ms);
  nlohmann::json e;
  e["ms"] = summaryJson(s);
  nlohmann::json ms_parts, ms_parts_p95;
  for (int p = 0; p < gpu::kPartCount; ++p) {
    const Summary part = summarize(parts[size_t(p)]);
    ms_parts[gpu::partName(gpu::Part(p))] = part.median;
    ms_parts_p95[gpu::partName(gpu::Part(p))] = part.p95;
  }
  // A composite's entries, within "reflect", by their `--assign` text.
  for (const auto& [label, ms] : r.entry_ms) {
    const Summary part = summarize(ms);
    ms_parts[label] = part.median;
    ms_parts_p95[label] = part.p95;
  }
  e["ms_parts"] = ms_parts;
  e["ms_parts_p95"] = ms_parts_p95;
  e["fps"] = orNull(1000.0 / s.median);
  e["frames"] = r.frames;
  e["clock"] = gpu::clockName(r.timer->clock());
  e["reflector_pixels"] = r.reflector_pixels;
  e["reflected_rays_per_s"] = orNull(double(r.reflector_pixels) * 1000.0 / s.median);
  e["order_rendered"] = r.method->orderRendered(settings.order);
  e["gpu_bytes"] = r.gpu_bytes;
  if (const std::string why = r.method->fallbackReason(); !why.empty()) e["fallback"] = why;
  nlohmann::json stats = nlohmann::json::object(), per_frame = nlohmann::json::object();
  for (const auto& [k, v] : r.method->stats()) stats[k] = orNull(v);
  // The work of a timed frame (re-captures, rebuilds, warped zexels...), on average.
  for (const auto& [k, sum] : r.counts) per_frame[k] = orNull(sum / double(r.frames));
  e["stats"] = stats;
  e["counts_per_frame"] = per_frame;
  return e;
}

// Every method's entry, with its median as a ratio to the baselines measured in the same run.
nlohmann::json methodsJson(std::vector<Run>& runs, const FrameSettings& settings) {
  std::map<std::string, nlohmann::json> entries;
  for (Run& r : runs) entries[r.name] = methodEntry(r, settings);
  auto median = [&](const std::string& name) {
    return entries[name]["ms"]["median"].get<double>();
  };
  nlohmann::json methods = nlohmann::json::object();
  for (Run& r : runs) {
    nlohmann::json& e = entries[r.name];
    auto ratio = [&](const char* base) {
      return entries.count(base) ? orNull(median(r.name) / median(base)) : nlohmann::json(nullptr);
    };
    e["ratio_to_none"] = ratio("none");
    e["ratio_to_envmap"] = ratio("envmap");
    e["ratio_to_raytrace"] = ratio("raytrace");
    methods[r.name] = e;
    spdlog::info("{:>16}: median {:8.2f} ms, min {:8.2f}, p95 {:8.2f} ({} frames)", r.name,
                 e["ms"]["median"].get<double>(), e["ms"]["min"].get<double>(),
                 e["ms"]["p95"].get<double>(), r.frames);
  }
  return methods;
}

// Resources held at each checkpoint, and a line that says whether they grew.
nlohmann::json resourcesJson(const std::vector<Resources>& resources) {
  nlohmann::json held = nlohmann::json::array();
  for (const Resources& r : resources)
    held.push_back({{"frame", r.frame},
                    {"rss_mib", r.rss_mib},
                    {"gl_handles", r.handles},
                    {"gl_objects", r.gl_objects}});
  const Resources &first = resources.front(), &last = resources.back();
  spdlog::info(
      "resources: RSS {:.1f} -> {:.1f} MiB, GL objects {} -> {}, handles {} -> {} "
      "(frames 0 -> {})",
      first.rss_mib, last.rss_mib, first.gl_objects, last.gl_objects, first.handles, last.handles,
      last.frame);
  return held;
}

// The run's description: scene, machine and settings.
nlohmann::json runJson(const Scene& scene, ivec2 size, const gpu::GlInfo& info,
                       const BenchArgs& args, const FrameSettings& settings,
                       const CameraDesc& camera) {
  nlohmann::json j;
  j["scene"] = scene.name;
  j["size"] = {size.x, size.y};
  j["device"] = info.renderer + " (" + info.version + ")";
  j["cpu"] = cpuDescription();
  j["allocator"] = processAllocator();
  const char* lp = std::getenv("LP_NUM_THREADS");
  j["lp_num_threads"] = lp ? nlohmann::json(lp) : nlohmann::json(nullptr);
  j["triangles"] = scene.triangleCount();
  j["objects"] = scene.instances.size();
  j["reflectors"] = scene.reflectorInstances().size();
  j["params"] = args.params;  // method parameters given on the command line
  j["order"] = settings.order;
  j["frames"] = args.frames;
  j["warmup"] = args.warmup;
  j["time"] = args.scene.time;
  j["fps"] = args.fps;
  j["camera"] = camera.name;
  return j;
}

int runBench(BenchArgs& args) {
  ivec2 size = parseSize(args.frame.size);
  FrameSettings settings = frameSettings(args.frame);
  validate(args);
  std::vector<std::string> names = parseMethodList(args.methods);
  warnUnusedParams(args.params, names);
  Scene scene = loadSceneFromArgs(args.scene);
  const CameraDesc& camera = scene.camera(args.scene.camera);
  size = imageSize(args.frame, camera);
  auto context = openHeadlessContext();
  FrameRenderer renderer(scene, size);
  // What every method shares: the scene's buffers, the frame's targets.
  const int64_t shared_bytes = gpu::allocatedBytes();
  std::vector<Run> runs =
      createRuns(renderer, names, args, settings, gpu::defaultClock(context->info().software));
  warmUp(runs, renderer, View(camera.at(args.scene.time), size), args, settings);
  const TimedFrames timed = timeFrames(runs, renderer, camera, size, args, settings);

  nlohmann::json j = runJson(scene, size, context->info(), args, settings, camera);
  j["gpu_bytes_shared"] = shared_bytes;
  if (args.fps > 0.0) j["scene_update_ms"] = summaryJson(summarize(timed.scene_ms));
  j["methods"] = methodsJson(runs, settings);
  j["resources"] = resourcesJson(timed.resources);
  writeFileAtomic(args.json, j.dump(2) + "\n");
  return 0;
}

}  // namespace

Command addBenchCommand(CLI::App& parent) {
  std::shared_ptr<BenchArgs> args;
  Command cmd = renderingCommand(parent, "bench",
                                 "time several methods on the same frames, in one run", args);
  addDefaulted(cmd.app, "--methods", args->methods, "all, or a comma-separated list of methods");
  addDefaulted(cmd.app, "--frames", args->frames, "timed frames per method (1..1000000)");
  addDefaulted(cmd.app, "--warmup", args->warmup, "untimed frames per method first (0..100000)");
  addDefaulted(cmd.app, "--fps", args->fps,
               "play the scene: timed frame i at --time + (i + 1) / fps, after warm-up frames "
               "at --time (0..1000; 0: every frame at --time, a still scene)");
  addDefaulted(cmd.app, "--raytrace-budget", args->raytrace_budget_s,
               "seconds the CPU ray tracer may spend on its timed frames (at least 3 frames)");
  addFrameOptions(cmd.app, args->frame);
  cmd.app->add_option("--json", args->json, "output JSON file")->required();
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runBench(*args); };
  return cmd;
}

}  // namespace mirage::app
