#include "methods/mixed/mixed_method.h"

#include "core/error.h"
#include "core/timer.h"
#include "gpu/gl.h"
#include "methods/assignment.h"

namespace mirage {

namespace {

// One assignment entry: its method, made for its reflectors.
struct Part {
  std::string label;
  std::optional<int> order;
  std::vector<int> reflectors;
  std::unique_ptr<Method> method;
  double ms = 0.0;  // its wall time in the last timed frame
};

std::vector<ReflectionRule> rulesOf(const MethodSetup& setup) {
  const std::string& text = setup.params.text(kAssignParam);
  if (!text.empty()) return parseAssignText(text);
  const Scene& scene = setup.gpu.scene();
  if (scene.reflections.empty())
    throwInput(
        "method 'mixed' needs an assignment: --assign 'NAMES=METHOD;...;*=METHOD' or the scene "
        "file's \"reflections\" (scene '{}' has none)",
        scene.name);
  return scene.reflections;
}

class MixedMethod final : public Method {
 public:
  explicit MixedMethod(const MethodSetup& setup) {
    const Assignment assignment = resolveAssignment(setup.gpu.scene(), rulesOf(setup));
    for (const AssignedPart& a : assignment.parts) {
      const MethodEntry& entry = findMethod(a.method);
      // The frame's values of the method's parameters, then the entry's own.
      std::map<std::string, std::string> given;
      for (const ParamSpec& spec : entry.info.params)
        given[spec.name] = setup.params.text(spec.name);
      for (const auto& [name, value] : a.params) given[name] = value;
      const ParamValues params = ParamValues::validate(entry.info.params, given, a.label);
      FrameSettings settings = setup.settings;
      if (a.order) settings.order = *a.order;
      if (settings.order < entry.info.min_order)
        throwInput("'{}': method '{}' needs order {}..{} (the frame's is {}; give :order=N)",
                   a.label, a.method, entry.info.min_order, kMaxOrder, settings.order);
      Part part{a.label, a.order, a.reflectors, nullptr};
      part.method = entry.create(
          {entry.info, setup.gpu, setup.passes, params, settings, assignment.parts.size() > 1});
      parts_.push_back(std::move(part));
    }
  }

  void update(FrameContext& frame) override {
    for (Part& part : parts_) {
      const FrameSettings settings = settingsOf(part, frame);
      FrameContext sub = partFrame(part, frame, settings);
      part.method->update(sub);
    }
  }

  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    timed_ = frame.timer != nullptr;
    for (Part& part : parts_) {
      if (timed_) glFinish();  // each part's own time, wall clock (gpu/frame_timer.h)
      Stopwatch clock;
      const FrameSettings settings = settingsOf(part, frame);
      FrameContext sub = partFrame(part, frame, settings);
      frame.target.bind();
      frame.passes.begin(frame.view, settings);
      part.method->render(sub);
      if (timed_) glFinish();
      part.ms = clock.ms();
    }
  }

  int orderRendered(int requested) const override {
    int out = 0;
    for (const Part& p : parts_)
      out = std::max(out, p.method->orderRendered(p.order.value_or(requested)));
    return out;
  }

  // Every part's stats, as "entry/stat".
  std::map<std::string, double> stats() const override {
    std::map<std::string, double> out;
    for (const Part& p : parts_)
      for (const auto& [name, value] : p.method->stats()) out[p.label + "/" + name] = value;
    return out;
  }

  std::vector<PartTime> partTimes() const override {
    std::vector<PartTime> out;
    if (!timed_) return out;
    for (const Part& p : parts_) out.push_back({p.label, p.ms});
    return out;
  }

 private:
  static FrameSettings settingsOf(const Part& part, const FrameContext& frame) {
    FrameSettings s = frame.settings;
    if (part.order) s.order = *part.order;
    return s;
  }
  static FrameContext partFrame(const Part& part, const FrameContext& frame,
                                const FrameSettings& settings) {
    FrameContext sub{frame.gpu, frame.passes, frame.target, frame.view, settings, nullptr};
    sub.own = &part.reflectors;
    sub.direct = false;
    return sub;
  }

  std::vector<Part> parts_;
  bool timed_ = false;
};

}  // namespace

MethodEntry mixedMethodEntry(std::span<const MethodEntry> methods) {
  MethodEntry entry;
  entry.info.name = "mixed";
  entry.info.description =
      "each reflector by the method an assignment gives it (--assign, or the scene's "
      "\"reflections\"): the direct part once, then every method over its own reflectors";
  entry.info.needs_assignment = true;
  entry.info.params = mergedParams(methods);
  entry.info.params.push_back(ParamSpec::text(
      kAssignParam, "NAMES=METHOD[:PARAM=VALUE...];...",
      "method mixed: which method draws which reflector, e.g. "
      "'mirror*=planar;ball=depthmap:srdm-m=16;*=envmap-box' (names: reflector or material "
      "names or globs; '*' the rest; default: the scene's \"reflections\")"));
  entry.create = factoryOf<MixedMethod>();
  return entry;
}

}  // namespace mirage
