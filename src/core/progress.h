// A progress bar for long work (ground-truth renders, captures, builds). It draws on stderr
// only when stderr is a terminal, so logs and CI output stay quiet. Thread-safe.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace mirage {

class Progress {
 public:
  // `total` 0: no bar (work too small or running in the background).
  Progress(std::string label, size_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(size_t n = 1);
  // Whether bars are drawn at all (stderr is a TTY and MIRAGE_NO_PROGRESS is unset).
  static bool enabled();

 private:
  void draw(size_t done, bool final);

  std::string label_;
  size_t total_;
  std::atomic<size_t> done_{0};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool active_;
};

}  // namespace mirage
