// `mirage compare --path-frames N`: quality along a walk. Every method renders the path's frames
// in order with one Method object, so that what it keeps between frames (captures, maps, a
// previous frame it reuses) works as in an animation. The frames are interleaved — frame f of the
// reference, then of every method, then frame f + 1 — so that only one reference frame is held
// at a time; each method still sees its own frames in sequence, the shared frame target being
// cleared for every frame anyway.
#include <algorithm>
#include <set>

#include <spdlog/spdlog.h>

#include "app/compare_analysis.h"
#include "app/compare_common.h"
#include "core/progress.h"
#include "eval/metrics.h"
#include "eval/temporal.h"

namespace mirage::app {

namespace {

struct PathMethod {
  std::string name;
  std::unique_ptr<Method> method;
  gpu::Clock clock = gpu::Clock::kWall;
  MethodReport report;
  TemporalError temporal;
};

// N equal steps from the path's first key to its last, both included (one frame: the first).
std::vector<float> pathTimes(const CameraPath& path, int frames) {
  std::vector<float> times;
  for (int i = 0; i < frames; ++i)
    times.push_back(frames == 1 ? path.start()
                                : path.start() + path.duration() * float(i) / float(frames - 1));
  return times;
}

// Means over the frames, the worst frame, and the steady frame time (the mean of the frames after
// the first, which does the captures and builds).
void summarize(MethodReport& m) {
  m.metrics = meanMetrics(m.frame_metrics);
  m.regions = meanRegions(m.frame_regions);
  m.worst = worstMetrics(m.frame_metrics);
  m.first_ms = m.frame_ms.front();
  double sum = 0.0;
  for (size_t i = 1; i < m.frame_ms.size(); ++i) sum += m.frame_ms[i];
  m.ms = m.frame_ms.size() > 1 ? sum / double(m.frame_ms.size() - 1) : m.first_ms;
  m.stats.clear();
  for (const auto& frame : m.frame_stats)
    for (const auto& [key, value] : frame) m.stats[key] += value / double(m.frame_stats.size());
}

}  // namespace

// Under --ssaa: every method again along the path at the output size, for its frame times and
// per-frame counters (what the quality run did at the larger size is not what a user would pay).
void timePathNative(CompareRun& run, const CameraDesc& camera, std::vector<PathMethod>& methods) {
  FrameSettings native = run.settings;
  native.pixel_scale = 1;
  const std::vector<float>& times = run.report.path.times;
  Progress progress("timing", times.size() * methods.size());
  for (PathMethod& p : methods) {
    p.method.reset();
    p.method = run.timing_renderer->createMethod(p.name, run.params, native);
    p.report.frame_ms.clear();
    p.report.frame_stats.clear();
    for (float time : times) {
      gpu::FrameTimer timer(p.clock);
      run.timing_renderer->render(*p.method, View(camera.at(time), run.size), time, native, &timer);
      p.report.frame_ms.push_back(timer.takeResults().front().total_ms);
      p.report.frame_stats.push_back(p.method->stats());
      progress.advance();
    }
  }
}

void comparePath(CompareRun& run, const CameraDesc& camera, int frames, int check_spp) {
  run.report.path.camera = camera.name;
  run.report.path.times = pathTimes(camera.path, frames);
  const std::vector<float>& times = run.report.path.times;
  const std::set<int> shown = {0, (frames - 1) / 2, frames - 1};

  std::vector<PathMethod> methods;
  for (const std::string& name : run.methods) {
    PathMethod p;
    p.name = name;
    p.method = run.renderer->createMethod(name, run.params, run.settings);
    p.clock = methodClock(run, *p.method);
    methods.push_back(std::move(p));
  }
  Progress progress("compare", size_t(frames) * methods.size());
  TemporalError reference_change;
  for (int f = 0; f < frames; ++f) {
    const float time = times[size_t(f)];
    const View view(camera.at(time), run.size), frame_view(camera.at(time), run.frame_size);
    ReferenceFrame reference;
    for (PathMethod& p : methods) {
      gpu::FrameTimer timer(p.clock);
      run.renderer->render(*p.method, frame_view, time, run.settings, &timer);
      p.report.frame_ms.push_back(timer.takeResults().front().total_ms);
      p.report.frame_stats.push_back(p.method->stats());
      const RenderedFrame frame = downsample(run.renderer->read(), run.ssaa);
      Image display = toDisplay(frame.color, run.display);
      if (&p == &methods.front()) {
        reference = {display, frame.ids, std::nullopt};
        reference.causes = traceCauses(run, frame_view, time, frame.ids);
        if (f == 0 && check_spp > 0) checkReference(run, view, time, reference, check_spp);
        reference_change.add(display, Image(display.width(), display.height()), frame.ids);
      }
      p.temporal.add(display, reference.display, reference.mask);
      Image2D<float> flip;
      p.report.frame_regions.emplace_back();
      p.report.frame_metrics.push_back(
          analyseFrame(run, display, reference, p.report.frame_regions.back(), &flip));
      if (shown.count(f)) {
        MapFiles files =
            writeMaps(run, fmt::format("{}.frame{}", p.name, f), display, reference.display, flip);
        p.report.shown.push_back({f, files.image, files.error_image, files.flip_image});
      }
      progress.advance();
    }
  }
  run.report.path.frame_reference_change = reference_change.perFrame();
  run.report.path.reference_change = reference_change.mean();
  if (run.timing_renderer) timePathNative(run, camera, methods);
  for (PathMethod& p : methods) {
    MethodReport m = describeMethod(run, p.name, *p.method);
    m.frame_metrics = std::move(p.report.frame_metrics);
    m.frame_regions = std::move(p.report.frame_regions);
    m.frame_ms = std::move(p.report.frame_ms);
    m.frame_stats = std::move(p.report.frame_stats);
    m.shown = std::move(p.report.shown);
    m.frame_temporal_error = p.temporal.perFrame();
    m.temporal_error = p.temporal.mean();
    summarize(m);
    spdlog::info(
        "{:>16}: {} frames, reflector PSNR mean {:6.2f} dB, worst {:6.2f}; FLIP reflector mean "
        "{:.4f}, worst {:.4f}; temporal error {:.4f}; {:8.2f} ms",
        m.name, frames, m.metrics.psnr_reflector, m.worst.psnr_reflector, m.metrics.flip_reflector,
        m.worst.flip_reflector, m.temporal_error, m.ms);
    run.report.methods.push_back(std::move(m));
  }
}

}  // namespace mirage::app
