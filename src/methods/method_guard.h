// What the frame renderer hands out instead of a bare method: the method, guarded. When the driver
// refuses it — a shader that does not compile, a texture or buffer beyond a driver limit, GPU
// memory exhausted (GpuError) — while it is made, updated or drawn, the guard says which with a
// warning and hands the frame to `envmap`, so that a user sees the scene with an approximate
// reflection and a reason instead of an error or a black image. Reports carry the reason.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "methods/method.h"

namespace mirage {

// How many times a guard of this process fell back (the tests' fixture fails a test in which a
// method fell back without the test expecting it: a fallback is not a pass).
long long methodFallbacks();

class MethodGuard : public Method {
 public:
  using Factory = std::function<std::unique_ptr<Method>()>;
  // Makes the method at once (a GpuError there already falls back); `fallback` makes envmap.
  MethodGuard(std::string requested, const Factory& make, Factory fallback);

  const MethodInfo& info() const override { return current_->info(); }
  void update(FrameContext& frame) override;
  void render(FrameContext& frame) override;
  int orderRendered(int requested) const override { return current_->orderRendered(requested); }
  std::map<std::string, double> stats() const override { return current_->stats(); }
  std::vector<PartTime> partTimes() const override { return current_->partTimes(); }
  std::string fallbackReason() const override { return reason_; }

 private:
  void fallBack(const GpuError& error);

  std::string requested_;
  Factory fallback_;
  std::unique_ptr<Method> current_;
  std::string reason_;
};

}  // namespace mirage
