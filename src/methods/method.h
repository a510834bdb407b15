// The interface every reflection method implements (docs/architecture.md, "Methods"), and the
// registry through which the tool, the viewer, the tests and the benchmarks find them. A method
// lives in its own folder under src/methods/; nothing outside reaches into it except through
// this header.
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/camera.h"
#include "gpu/frame_timer.h"
#include "methods/params.h"
#include "render/frame_target.h"
#include "render/gpu_scene.h"
#include "render/scene_passes.h"

namespace mirage {

struct ProbeLookup;

inline constexpr int kAnyOrder = 1 << 20;

struct MethodInfo {
  std::string name;
  std::string description;
  int max_order = kAnyOrder;  // the highest reflection order it can produce
  int min_order = 0;          // the lowest --order it accepts (billboards need a reflection)
  bool gpu = true;            // false: renders on the CPU (the ray tracer)
  // It draws by an assignment (`mixed`): not part of "--methods all", which compares the
  // methods themselves.
  bool needs_assignment = false;
  std::vector<ParamSpec> params;
  // Stats that count work since the method was made (captures, builds, rays): a frame's share is
  // their growth over that frame, 0 in a frame that redid nothing.
  std::vector<std::string> counters;
  // Stats that describe the last frame alone (zexels warped, kd leaves kept, mirrored views).
  std::vector<std::string> frame_stats;
};

// What a method did in one frame, from its stats before and after the frame: each counter's
// growth and each frame stat's value, by name — the counts that show what a dynamic scene costs
// (the viewer shows them per frame, `mirage bench` their mean per frame).
std::map<std::string, double> frameCounts(const MethodInfo& info,
                                          const std::map<std::string, double>& before,
                                          const std::map<std::string, double>& after);

// What a method is created with: the scene on the GPU and its validated parameters. `info`, `gpu`
// and `passes` outlive the method (the registry's, the frame renderer's); `params` and
// `settings` live only while it is made: a method copies what it needs of them in its
// constructor, so that the frame renderer keeps nothing per method made (the viewer makes one at
// every switch).
struct MethodSetup {
  const MethodInfo& info;  // the registry's entry (lives as long as the program)
  GpuScene& gpu;
  ScenePasses& passes;
  const ParamValues& params;
  const FrameSettings& settings;
  // Made for a composite (`mixed` with several entries): the reflectors it does not own are
  // drawn by other methods, and `planar` shows curved ones in its mirrored views through probes.
  bool composite = false;
};

// What a method renders a frame with.
struct FrameContext {
  GpuScene& gpu;
  ScenePasses& passes;
  FrameTarget& target;
  const View& view;
  const FrameSettings& settings;
  gpu::FrameTimer* timer = nullptr;  // null when not timing
  // The reflectors this method draws in the eye view, instances in scene order; null: every
  // reflector. Method `mixed` gives each assigned method its own and draws the direct part once
  // itself (direct = false). Within its bounces and captures a method still shows every
  // reflector its own way.
  const std::vector<int>* own = nullptr;
  bool direct = true;

  // Whether this method draws reflector `instance` in the eye view.
  bool owns(int instance) const {
    return !own || std::find(own->begin(), own->end(), instance) != own->end();
  }
  // The direct part of the eye view (background and diffuse objects), unless drawn already.
  void drawDirect() const {
    if (direct) passes.drawDirect();
  }
  // This method's reflectors in the eye view, with `program`.
  void drawOwnReflectors(const gpu::Program& program) const {
    if (own)
      passes.drawReflectorInstances(program, *own);
    else
      passes.drawReflectors(program);
  }

  void beginPart(gpu::Part part) const {
    if (timer) timer->beginPart(part);
  }
  // What Method::render starts from: the target bound and cleared, the shared passes set up for
  // this view (the frame renderer before every render, the method guard when it redraws).
  void beginDrawing() const {
    target.bind();
    target.clear();
    passes.begin(view, settings);
  }
};

class Method {
 public:
  virtual ~Method() = default;

  // The registry's entry of the method, attached by factoryOf as it makes the method (not yet
  // there while the method's constructor runs).
  virtual const MethodInfo& info() const {
    MIRAGE_CHECK(info_ != nullptr);  // made by its entry's factory (factoryOf)
    return *info_;
  }
  void attachInfo(const MethodInfo& info) { info_ = &info; }
  // Brings captures and builds up to date with the scene at gpu.time(): rebuild only what
  // changed since the last call (a camera move alone changes nothing a method captures).
  virtual void update(FrameContext& frame) = 0;
  // Draws the frame into frame.target (already bound and cleared): the direct part (the timer
  // is already in part kDirect, which holds the clear too), then the reflections after
  // frame.beginPart(kReflect).
  virtual void render(FrameContext& frame) = 0;
  // The reflection order this method produces when K is requested.
  virtual int orderRendered(int requested) const { return std::min(requested, info().max_order); }
  // Counters for reports and tests: captures made, structures built, ...
  virtual std::map<std::string, double> stats() const { return {}; }
  // The reflection probes this method shades its reflectors with, as another pass looks them up
  // (`ssr` shades the pixels its screen cannot show with its fallback's), or null: none, or not
  // captured yet (after update() they are).
  virtual const ProbeLookup* probeLookup() const { return nullptr; }
  // Why `envmap` draws in this method's place (the driver refused it: methods/method_guard.h),
  // or empty.
  virtual std::string fallbackReason() const { return {}; }
  // The wall time of each part of the last frame drawn with a timer, for methods made of parts
  // (`mixed`: one per assignment entry, labelled as the entry), else empty.
  struct PartTime {
    std::string label;
    double ms = 0.0;
  };
  virtual std::vector<PartTime> partTimes() const { return {}; }

 private:
  const MethodInfo* info_ = nullptr;
};

using MethodFactory = std::function<std::unique_ptr<Method>(const MethodSetup&)>;

struct MethodEntry {
  MethodInfo info;
  MethodFactory create;
};

// The factory of method class M, made from the setup and `extra` (a variant, say).
template <class M, class... Extra>
MethodFactory factoryOf(Extra... extra) {
  return [=](const MethodSetup& setup) -> std::unique_ptr<Method> {
    std::unique_ptr<Method> method = std::make_unique<M>(setup, extra...);
    method->attachInfo(setup.info);
    return method;
  };
}

// Every method, in the order reports list them.
const std::vector<MethodEntry>& methodRegistry();
std::vector<std::string> methodNames();
// The entry of `name`; throws InputError listing the allowed names.
const MethodEntry& findMethod(const std::string& name);
// "all" or a comma-separated list, each name checked.
std::vector<std::string> parseMethodList(const std::string& list);
// Every parameter of `entries`, once per name, in the order first listed; methods that share a
// parameter must declare it alike (name, type, range, default, choices, help), else
// an internal error (core/check.h) names both methods: a programming error, not an input error.
std::vector<ParamSpec> mergedParams(std::span<const MethodEntry> entries);
// mergedParams of the registry (for the command line and the viewer).
std::vector<ParamSpec> allMethodParams();

}  // namespace mirage
