// The viewer's ground truth: the ray tracer renders the current view on a background thread at
// a reduced resolution, refining progressively — a quarter and a half of that resolution first,
// then all of it, then as many samples a pixel as the frame has pixels in it, at their very
// positions (matched sampling: the frame's divisor x divisor pixels, each of --ssaa N x N
// sub-pixels) — and drops what it is doing when the view changes (the
// camera, the scene time, the order or the size), starting over for the new one. The viewer
// keeps drawing at its own rate and shows the newest finished image.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/camera.h"
#include "core/image.h"
#include "scene/environment.h"
#include "scene/scene.h"

namespace mirage {

struct TruthRequest {
  CameraDesc camera;
  ivec2 size{1};    // the viewer's frame size
  int divisor = 2;  // the reference's resolution is size / divisor
  int ssaa = 1;     // the frame's sub-pixels per window pixel along each side (--ssaa)
  float time = 0.0f;
  int order = 1;

  bool operator==(const TruthRequest& o) const;
  // The image size of refinement `level` (0 .. kLevels - 1).
  ivec2 levelSize(int level) const;
  static constexpr int kLevels = 4;
  // The last level traces the frame's own sample positions within each reference pixel: a
  // regular grid of (divisor * ssaa)^2 (the ray tracer's strata centres).
  int levelSpp(int level) const {
    return level == kLevels - 1 ? (divisor * ssaa) * (divisor * ssaa) : 1;
  }
};

struct TruthImage {
  TruthRequest request;
  Image color;  // linear radiance, top row first
  IdImage ids;
  int level = -1;  // -1: none yet
  double ms = 0.0;
  uint64_t serial = 0;  // increments with every image published
};

class TruthRenderer {
 public:
  // `threads`: the ray tracer's share of the cores (the viewer draws on the rest).
  TruthRenderer(const Scene& scene, const EnvironmentMap& environment, int threads);
  ~TruthRenderer();
  TruthRenderer(const TruthRenderer&) = delete;
  TruthRenderer& operator=(const TruthRenderer&) = delete;

  // Renders this view; the same view as the last request keeps its progress.
  void request(const TruthRequest& request);
  // Stops the current work (the thread idles until the next request).
  void cancel();
  // Copies the newest image into `out` when it is newer than out.serial.
  bool takeNewer(TruthImage& out);
  // The level being rendered (-1 when idle), for the panel.
  int working() const { return working_.load(); }
  // Why the thread stopped for good (the ray tracer failed), or "".
  std::string failure();

 private:
  void run();
  void work();

  const Scene& scene_;
  EnvironmentMap environment_;  // a copy: the viewer's renderer is remade on resize
  int threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<TruthRequest> pending_;  // guarded by mutex_
  std::optional<TruthRequest> current_;  // guarded by mutex_: what the thread works on or did
  TruthImage latest_;                    // guarded by mutex_
  std::string failure_;                  // guarded by mutex_
  std::atomic<bool> cancel_{false}, quit_{false};
  std::atomic<int> working_{-1};
  std::thread thread_;
};

}  // namespace mirage
