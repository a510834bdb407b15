#include "core/progress.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

namespace mirage {

bool Progress::enabled() {
  static const bool on = ::isatty(STDERR_FILENO) && !std::getenv("MIRAGE_NO_PROGRESS");
  return on;
}

Progress::Progress(std::string label, size_t total)
    : label_(std::move(label)),
      total_(std::max<size_t>(total, 1)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_),
      active_(enabled() && total > 0) {}

Progress::~Progress() {
  if (active_) draw(done_.load(), true);
}

void Progress::advance(size_t n) {
  size_t done = done_.fetch_add(n) + n;
  if (!active_) return;
  auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100) && done < total_) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  last_draw_ = now;
  draw(done, false);
}

void Progress::draw(size_t done, bool final) {
  constexpr int kWidth = 30;
  double fraction = std::min(1.0, double(done) / double(total_));
  int filled = int(fraction * kWidth);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string bar(size_t(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %3d%% %.1fs%s", label_.c_str(), bar.c_str(),
               int(fraction * 100.0), seconds, final ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace mirage
