#include "viewer/truth_renderer.h"

#include <tbb/task_arena.h>

#include "core/timer.h"
#include "raytrace/tracer.h"

namespace mirage {

bool TruthRequest::operator==(const TruthRequest& o) const {
  const CameraDesc &a = camera, &b = o.camera;
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.fov_y_degrees == b.fov_y_degrees && a.near_plane == b.near_plane &&
         a.far_plane == b.far_plane && size == o.size && divisor == o.divisor && ssaa == o.ssaa &&
         time == o.time && order == o.order;
}

ivec2 TruthRequest::levelSize(int level) const {
  const int shrink = divisor << std::max(0, kLevels - 2 - level);  // /4, /2, /1, /1 (matched)
  return glm::max(ivec2(8), size / shrink);
}

TruthRenderer::TruthRenderer(const Scene& scene, const EnvironmentMap& environment, int threads)
    : scene_(scene), environment_(environment), threads_(std::max(threads, 1)) {
  thread_ = std::thread([this] { run(); });
}

TruthRenderer::~TruthRenderer() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void TruthRenderer::request(const TruthRequest& request) {
  {
    std::lock_guard lock(mutex_);
    if ((current_ && *current_ == request && !pending_) || (pending_ && *pending_ == request))
      return;
    pending_ = request;
    cancel_ = true;
  }
  wake_.notify_all();
}

void TruthRenderer::cancel() {
  std::lock_guard lock(mutex_);
  pending_.reset();
  current_.reset();
  cancel_ = true;
}

bool TruthRenderer::takeNewer(TruthImage& out) {
  std::lock_guard lock(mutex_);
  if (latest_.serial <= out.serial) return false;
  out = latest_;
  return true;
}

std::string TruthRenderer::failure() {
  std::lock_guard lock(mutex_);
  return failure_;
}

void TruthRenderer::run() {
  try {
    work();
  } catch (const std::exception& e) {
    // Nothing may escape a thread; the viewer shows the reason and draws on without a reference.
    std::lock_guard lock(mutex_);
    failure_ = e.what();
    working_ = -1;
  }
}

void TruthRenderer::work() {
  // Its own arena: the tracer's tiles use `threads_` workers and leave the rest to the viewer.
  tbb::task_arena arena(threads_);
  RayTracer tracer(scene_, environment_);
  TraceResult result;
  for (;;) {
    TruthRequest request;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      request = *pending_;
      pending_.reset();
      current_ = request;
      cancel_ = false;
    }
    for (int level = 0; level < TruthRequest::kLevels && !cancel_; ++level) {
      working_ = level;
      Stopwatch watch;
      TraceSettings settings{request.order, request.levelSpp(level), &cancel_, false};
      arena.execute([&] {
        tracer.prepare(request.time);
        tracer.render(View(request.camera, request.levelSize(level)), settings, result);
      });
      if (cancel_) break;
      std::lock_guard lock(mutex_);
      latest_.request = request;
      latest_.color = result.color;
      latest_.ids = result.ids;
      latest_.level = level;
      latest_.ms = watch.ms();
      ++latest_.serial;
    }
    working_ = -1;
  }
}

}  // namespace mirage
