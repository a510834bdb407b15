#include "methods/hybrid/splat_pass.h"

#include <algorithm>
#include <numeric>
#include <span>

#include "core/timer.h"
#include "gpu/context.h"
#include "gpu/loop_budget.h"
#include "methods/hybrid/c3rc_frame.h"

namespace mirage {

namespace {

// The runs of work items one workgroup projects (itemRuns). A software rasteriser runs each
// workgroup as a task of one SIMD batch with its own set-up, and a run of one C3RC's items loads
// the C3RC once: runs of up to 64 items took teapot-dragon's splatting from 39 to 35 ms on
// llvmpipe. A GPU needs many workgroups to fill its cores: one item a run there. Either way a
// run stays within the loop budget (gpu/loop_budget.h): llvmpipe ends a shader's loops after
// 65,535 iterations in all.
constexpr size_t kRunItemsSoftware = 64;

}  // namespace

SplatPass::SplatPass(const SplatSettings& settings)
    : settings_(settings),
      program_(gpu::Program::compute("methods/hybrid/hybrid_splat.comp")),
      run_items_(gpu::currentContextIsSoftware() ? kRunItemsSoftware : 1) {}

long long SplatPass::pointCost(const SplatSettings& settings) {
  const long long side = settings.splat_size > 0
                             ? settings.splat_size
                             : (long long)MIRAGE_HYBRID_MAX_SPLAT * settings.pixel_scale;
  const long long project =
      gpu::loopCost(MIRAGE_C3RC_HULL) + gpu::loopCost(3, gpu::loopCost(MIRAGE_C3RC_ROOT_STEPS));
  const long long splats = gpu::loopCost(settings.first_only ? 1 : 3, gpu::loopCost(side * side));
  return project + splats;
}

RunLimits SplatPass::runLimits() const {
  return {pointCost(settings_), gpu::kShaderLoopBudget, run_items_, MIRAGE_HYBRID_GROUP};
}

long long SplatPass::slicePoints() const {
  // One item from its first point: the run's item loop (1), the item's iteration and its point
  // loop's last test (2), then steps of MIRAGE_HYBRID_GROUP points.
  const long long steps = (gpu::kShaderLoopBudget - 3) / (1 + pointCost(settings_));
  return steps * MIRAGE_HYBRID_GROUP;
}

std::vector<SplatRun> SplatPass::runs(const SplatItems& items) const {
  return itemRuns(*items.cpu, runLimits());
}

void SplatPass::dispatch(size_t run_count) {
  // At most 65,535 workgroups a dispatch (GL's minimum limit), one run each.
  for (size_t base = 0; base < run_count; base += 65535) {
    program_.set("u_run_base", int(base));
    glDispatchCompute(GLuint(std::min<size_t>(run_count - base, 65535)), 1, 1);
  }
}

std::vector<uint32_t> SplatPass::seenPerItem(size_t items) const {
  std::vector<uint32_t> seen(items, 0u);
  if (items > 0 && seen_buffer_.size() >= items * sizeof(uint32_t))
    seen_buffer_.download(seen.data(), items * sizeof(uint32_t));
  return seen;
}

void SplatPass::run(FrameContext& frame, PointStore& store, const std::vector<C3rcData>& c3rcs,
                    const gpu::Texture& reflector_ids, const SplatItems& items, bool count_only) {
  const ivec2 size = frame.target.size();
  visibility_.begin(size_t(size.x) * size_t(size.y));
  if (counter_buffer_.size() == 0) counter_buffer_ = gpu::Buffer(sizeof(counters_));
  store.bind(MIRAGE_BIND_HYBRID_POINTS, MIRAGE_BIND_HYBRID_POINT_ATTRIBUTES);
  ms_ = 0.0;
  std::fill(std::begin(counters_), std::end(counters_), 0u);
  if (items.count == 0) return;

  c3rc_buffer_.upload(std::span<const C3rcData>(c3rcs));
  if (seen_buffer_.size() < std::max<size_t>(items.count, 1) * sizeof(uint32_t))
    seen_buffer_ = gpu::Buffer(std::max<size_t>(items.count, 1) * sizeof(uint32_t));
  if (count_only) SplatVisibility::clearWords(seen_buffer_, 0u);
  seen_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_ITEM_SEEN);
  program_.set("u_count_only", count_only ? 1 : 0);
  if (items.cpu) item_buffer_.upload(std::span<const ivec4>(*items.cpu));
  c3rc_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_C3RCS);
  (items.cpu ? item_buffer_ : *items.gpu)
      .bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_ITEMS);
  counter_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_COUNTERS);
  frame.target.depth().bind(MIRAGE_UNIT_HYBRID_DEPTH);
  reflector_ids.bind(MIRAGE_UNIT_HYBRID_IDS);
  size_t run_count = 0;
  if (items.cpu) {
    const std::vector<SplatRun> item_runs = runs(items);
    run_buffer_.upload(std::span<const SplatRun>(item_runs));
    run_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_RUNS);
    run_count = item_runs.size();
    program_.set("u_slices", 0);
  } else {
    const long long slice = slicePoints();
    const long long slices = std::max<long long>((items.gpu_points + slice - 1) / slice, 1);
    run_count = items.count * size_t(slices);
    if (run_buffer_.size() == 0) run_buffer_ = gpu::Buffer(sizeof(SplatRun));
    run_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_RUNS);
    program_.set("u_slices", int(slices));
    program_.set("u_slice_points", int(slice));
  }
  const mat4& proj = frame.view.projectionMatrix();
  program_.set("u_run_count", int(run_count));
  program_.set("u_first_only", settings_.first_only ? 1 : 0);
  program_.set("u_splat_size", settings_.splat_size);
  program_.set("u_pixel_scale", settings_.pixel_scale);
  program_.set("u_proj", vec2(proj[2][2], proj[3][2]));
  program_.set("u_occlusion", 0.01f);
  program_.set("u_keep_backfaces", settings_.keep_backfaces ? 1 : 0);
  const bool timing = frame.timer != nullptr;
  if (timing) glFinish();
  Stopwatch watch;
  size_t candidates = 0;
  do {  // again, with a larger candidate buffer, when the candidates overflowed it
    program_.set("u_candidate_capacity", int(visibility_.prepare()));
    SplatVisibility::clearWords(counter_buffer_, 0u);
    program_.use();
    dispatch(run_count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    counter_buffer_.download(counters_, sizeof(counters_));
    candidates = counters_[MIRAGE_HYBRID_COUNTER_CANDIDATES];
  } while (!visibility_.fitted(candidates));
  if (!count_only) visibility_.pickWinners(candidates);
  if (timing) {
    glFinish();
    ms_ = watch.ms();
  }
}

}  // namespace mirage
