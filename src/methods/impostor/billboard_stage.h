// The billboard half of the impostor paper's reflected scene, as every impostor method uses it:
// billboards placed (billboard_set.h) and captured (billboard_capture.h), their storage
// buffers, and the environment the reflections miss into (captured at the reflectors' centroid
// when objects without impostors, or the morphing ground, must appear in it). `billboard` draws
// with this alone; `depthmap` adds depth-map impostors for the objects it takes out of it.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/counter_slots.h"
#include "gpu/loop_budget.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/impostor/billboard_capture.h"
#include "methods/impostor/billboard_set.h"
#include "methods/impostor/impostor_groups.h"
#include "methods/impostor/impostor_shader.h"
#include "methods/method.h"
#include "render/cube_capture.h"
#include "render/recapture.h"
#include "render/reflector_gbuffer.h"

namespace mirage {

struct BillboardStageOptions {
  BillboardSetOptions set;
  int billboard_size = 256;          // texels per billboard side
  int envmap_size = 256;             // face size of the captured environment
  RecapturePolicy recapture;         // moving scenes: when billboards are re-captured
  GroupSetting groups;               // --impostor-groups
  uint64_t memory_cap = 2ull << 30;  // --impostor-memory, bytes
};

// The parameters every impostor method takes for its billboards, and the options they make.
std::vector<ParamSpec> billboardStageParams();
BillboardStageOptions billboardStageOptions(const ParamValues& params);
// The caps of --impostor-groups auto: the driver's texture layers, --impostor-memory.
GroupCaps impostorGroupCaps(const BillboardStageOptions& options);
// What the stage's textures cost as a function of its group count (impostor_groups.h): the
// planar objects' and the reflective billboards' layers, the capture's depth, the environment
// cube where something has no billboard, and a billboard a reflector per group.
GroupCost billboardStageCost(const Scene& scene, const BillboardStageOptions& options);

// The worst case of impostor_trace.glsl's loops in one invocation (gpu/loop_budget.h): `order`
// bounces, each testing a list of `list` entries (nearest_billboard) and running the method's
// hooks at `hooks` a bounce.
constexpr long long impostorTraceLoopCost(int order, long long list, long long hooks) {
  return gpu::loopCost(order, gpu::loopCost(list) + hooks);
}
// --last-bounce all: the last bounce tests reflective billboards too (a hit shows its base colour).
bool lastBounceReflective(const ParamValues& params);

// What an impostor method's hooks cost a bounce of the trace, in the loop limiter's count, and
// the settings behind it (said when it is beyond the budget).
struct ImpostorHookCost {
  long long cost = 0;
  std::string settings;
};

class BillboardStage {
 public:
  // Groups the scene's billboarded objects (--impostor-groups; needs a current context for the
  // driver's limits): throws GpuError when not even one group fits, saying what would.
  BillboardStage(const BillboardStageOptions& options, const Scene& scene);

  // Places the billboards and re-captures those that drifted beyond the tolerances since their
  // capture, within the budget (nothing for a camera move; every one the first time).
  void update(FrameContext& frame);
  // Binds the buffers, textures and morph uniforms that impostor_trace.glsl reads.
  void bind(const gpu::Program& program, const GpuScene& gpu) const;
  // An impostor method's frame up to its reflections: the direct part; then, when there is
  // something to trace (order >= 1 and reflectors), binds the stage and the last-bounce rule
  // for `shader`'s programs and returns true; otherwise draws the reflectors with
  // `base_program` (their base colour) and returns false. `hooks`: what the method's hooks
  // cost a bounce in the loop limiter's count (impostorTraceLoopCost) and the settings that
  // make it, for the message; the trace's worst case beyond the loop budget is a GpuError
  // (gpu/loop_budget.h).
  bool beginFrame(FrameContext& frame, const ImpostorShader& shader,
                  const gpu::Program& base_program, bool last_bounce_reflective,
                  const ImpostorHookCost& hooks = ImpostorHookCost{}) const;
  // The most entries a ray's list holds, diffuse and reflective, over every list and side: what
  // a bounce of the trace loops over.
  int longestList() const;
  bool empty() const { return set_.ranges.empty(); }
  // The defines impostor_trace.glsl needs for these options (IMPOSTOR_MORPH: the morph's box).
  std::vector<std::string> shaderDefines() const;
  // The stats every impostor method's frame reports (MethodInfo::frame_stats): the impostors a
  // reflected ray tested on average and the rays a reflector pixel traced, in the last frame.
  static std::vector<std::string> frameStats();
  const BillboardSet& set() const { return set_; }
  std::map<std::string, double> stats() const;

 private:
  Drift environmentDrift(const GpuScene& gpu, const std::vector<int>& instances);
  void captureEnvironment(FrameContext& frame, const std::vector<int>& instances);

  BillboardStageOptions options_;
  Grouping grouping_;
  BillboardCapture capture_;
  BillboardSet set_;
  gpu::Buffer billboards_, carries_, ranges_, entries_;
  // The trace's counts (impostor_counts.glsl), zeroed at each frame's start.
  mutable gpu::CounterSlots counts_{MIRAGE_IMPOSTOR_COUNTS};
  gpu::Texture environment_;
  std::unique_ptr<CubeCapture> cube_;
  ProbeRecapture env_state_;  // what the environment showed when captured
  long env_captures_ = 0;
  int last_captures_ = 0;
  bool updated_ = false;
  uint64_t updated_version_ = 0;
};

}  // namespace mirage
