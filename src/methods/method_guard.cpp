#include "methods/method_guard.h"

#include <atomic>

#include <spdlog/spdlog.h>

#include "core/error.h"

namespace mirage {

namespace {

std::atomic<long long> g_fallbacks{0};

// Runs `attempt`; where the driver refuses it (a GpuError), `recover` gets the error.
template <typename Attempt, typename Recover>
void orRecover(Attempt&& attempt, Recover&& recover) {
  try {
    attempt();
  } catch (const GpuError& e) {
    recover(e);
  }
}

}  // namespace

long long methodFallbacks() {
  return g_fallbacks.load();
}

MethodGuard::MethodGuard(std::string requested, const Factory& make, Factory fallback)
    : requested_(std::move(requested)), fallback_(std::move(fallback)) {
  orRecover([&] { current_ = make(); }, [&](const GpuError& e) { fallBack(e); });
}

void MethodGuard::fallBack(const GpuError& error) {
  if (!reason_.empty())  // envmap itself was refused: nothing simpler is left to draw with
    throwGpu("method '{}' fell back to 'envmap' ({}), which the driver refused too: {}", requested_,
             reason_, error.what());
  reason_ = error.what();
  ++g_fallbacks;
  spdlog::warn("method '{}' cannot run on this OpenGL driver: {}; drawing with 'envmap' instead",
               requested_, reason_);
  current_.reset();  // its GL objects go before envmap makes its own
  orRecover([&] { current_ = fallback_(); }, [&](const GpuError& e) { fallBack(e); });
}

void MethodGuard::update(FrameContext& frame) {
  orRecover([&] { current_->update(frame); },
            [&](const GpuError& e) {
              fallBack(e);
              current_->update(frame);
            });
}

void MethodGuard::render(FrameContext& frame) {
  orRecover([&] { current_->render(frame); },
            [&](const GpuError& e) {
              fallBack(e);
              // The refused method may have drawn part of the frame: start it again, with
              // envmap's captures made first.
              current_->update(frame);
              frame.beginDrawing();
              current_->render(frame);
            });
}

}  // namespace mirage
