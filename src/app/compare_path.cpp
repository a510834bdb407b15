// `mirage compare --path-frames N`: quality along a walk. Every method renders the path's frames
// in order with one Method object, so that what it keeps between frames (captures, maps, a
// previous frame it reuses) works as in an animation. The frames are interleaved — frame f of the
// reference, then of every method, then frame f + 1 — so that only one reference frame is held
// at a time; each method still sees its own frames in sequence, the shared frame target being
// cleared for every frame anyway.
#include <algorithm>
#include <set>

#include <spdlog/spdlog.h>

#include "app/compare_common.h"
#include "core/progress.h"
#include "eval/metrics.h"

namespace mirage::app {

namespace {

struct PathMethod {
  std::string name;
  std::unique_ptr<Method> method;
  gpu::Clock clock = gpu::Clock::kWall;
  MethodReport report;
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

void comparePath(CompareRun& run, const CameraDesc& camera, int frames) {
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
  for (int f = 0; f < frames; ++f) {
    const float time = times[size_t(f)];
    const View view(camera.at(time), run.size);
    Image reference;
    IdImage mask;
    for (PathMethod& p : methods) {
      gpu::FrameTimer timer(p.clock);
      run.renderer->render(*p.method, view, time, run.settings, &timer);
      p.report.frame_ms.push_back(timer.takeResults().front().total_ms);
      p.report.frame_stats.push_back(p.method->stats());
      RenderedFrame frame = run.renderer->read();
      Image display = toDisplay(frame.color, run.display);
      if (&p == &methods.front()) {
        reference = display;
        mask = frame.ids;
      }
      Image2D<float> flip;
      p.report.frame_metrics.push_back(compareImages(display, reference, mask, &flip));
      if (shown.count(f)) {
        MapFiles files =
            writeMaps(run, fmt::format("{}.frame{}", p.name, f), display, reference, flip);
        p.report.shown.push_back({f, files.image, files.error_image, files.flip_image});
      }
      progress.advance();
    }
  }
  for (PathMethod& p : methods) {
    MethodReport m = describeMethod(run, p.name, *p.method);
    m.frame_metrics = std::move(p.report.frame_metrics);
    m.frame_ms = std::move(p.report.frame_ms);
    m.frame_stats = std::move(p.report.frame_stats);
    m.shown = std::move(p.report.shown);
    summarize(m);
    spdlog::info(
        "{:>16}: {} frames, reflector PSNR mean {:6.2f} dB, worst {:6.2f}; FLIP reflector mean "
        "{:.4f}, worst {:.4f}; {:8.2f} ms",
        m.name, frames, m.metrics.psnr_reflector, m.worst.psnr_reflector, m.metrics.flip_reflector,
        m.worst.flip_reflector, m.ms);
    run.report.methods.push_back(std::move(m));
  }
}

}  // namespace mirage::app
