#include "methods/frame.h"

#include "core/error.h"
#include "core/interrupt.h"
#include "core/supersample.h"
#include "methods/method_guard.h"

namespace mirage {

FrameRenderer::FrameRenderer(const Scene& scene, ivec2 size)
    : scene_(scene),
      environment_(EnvironmentMap::forScene(scene)),
      gpu_(std::make_unique<GpuScene>(scene, environment_)),
      passes_(std::make_unique<ScenePasses>(*gpu_)),
      target_(size) {}

std::unique_ptr<Method> FrameRenderer::createMethod(const std::string& name,
                                                    const std::map<std::string, std::string>& given,
                                                    const FrameSettings& settings) {
  const MethodEntry& entry = findMethod(name);
  if (settings.order < entry.info.min_order)
    throwInput("method '{}': --order {} is out of range (allowed: {}..{})", name, settings.order,
               entry.info.min_order, kMaxOrder);
  std::map<std::string, std::string> own;
  for (const ParamSpec& spec : entry.info.params)
    if (auto it = given.find(spec.name); it != given.end()) own[spec.name] = it->second;
  // A method reads its setup while it is made and keeps copies of what it needs (method.h), so
  // the parameters live only for this call; the fallback, made later if at all, keeps its own
  // copy of the settings.
  const ParamValues params = ParamValues::validate(entry.info.params, own, name);
  if (name == "envmap") return entry.create({entry.info, *gpu_, *passes_, params, settings});
  // Every other method falls back to envmap (default parameters) when the driver refuses it.
  return std::make_unique<MethodGuard>(
      name,
      [&] {
        return entry.create({entry.info, *gpu_, *passes_, params, settings});
      },
      [this, settings] { return createMethod("envmap", {}, settings); });
}

void FrameRenderer::render(Method& method, const View& view, float time,
                           const FrameSettings& settings, gpu::FrameTimer* timer,
                           std::map<std::string, double>* counts) {
  // Every command's frame loop passes here: Ctrl-C stops it between frames.
  checkInterrupt();
  if (view.size() != target_.size())
    throwRuntime("view size {}x{} differs from the frame size {}x{}", view.size().x, view.size().y,
                 target_.size().x, target_.size().y);
  FrameContext frame{*gpu_, *passes_, target_, view, settings, timer};
  const std::map<std::string, double> before =
      counts ? method.stats() : std::map<std::string, double>{};
  if (timer) timer->beginFrame();
  frame.beginPart(gpu::Part::kUpdate);
  gpu_->setTime(time);
  method.update(frame);
  // The clear is part of drawing the frame, not of bringing captures up to date.
  frame.beginPart(gpu::Part::kDirect);
  frame.beginDrawing();
  method.render(frame);
  if (timer) timer->endFrame();
  if (counts) *counts = frameCounts(method.info(), before, method.stats());
}

RenderedFrame downsample(RenderedFrame frame, int n) {
  if (n == 1) return frame;
  return {boxDownsample(frame.color, n), majorityDownsample(frame.ids, n)};
}

RenderedFrame FrameRenderer::read() const {
  return {target_.readColor(), target_.readIds()};
}

}  // namespace mirage
