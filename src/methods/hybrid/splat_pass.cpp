#include "methods/hybrid/splat_pass.h"

#include <algorithm>
#include <numeric>
#include <span>

#include "core/timer.h"
#include "gpu/context.h"
#include "methods/hybrid/c3rc_frame.h"

namespace mirage {

namespace {

// The runs of work items one workgroup projects (itemRuns). A software rasteriser runs each
// workgroup as a task of one SIMD batch with its own set-up, and a run of one C3RC's items loads
// the C3RC once: runs of up to 64 items took teapot-dragon's splatting from 39 to 35 ms on
// llvmpipe. At most kMaxItemPoints points a run, as a merged item holds: llvmpipe ends a shader
// after 65,535 loop iterations. A GPU needs many workgroups to fill its cores: one item a run
// there.
constexpr size_t kRunItemsSoftware = 64;

}  // namespace

SplatPass::SplatPass(const SplatSettings& settings)
    : settings_(settings),
      program_(gpu::Program::compute("methods/hybrid/hybrid_splat.comp")),
      run_items_(gpu::currentContextIsSoftware() ? kRunItemsSoftware : 1) {}

std::vector<uint32_t> SplatPass::runs(const SplatItems& items) const {
  if (items.cpu) return itemRuns(*items.cpu, kMaxItemPoints, run_items_);
  std::vector<uint32_t> runs(items.count + 1);
  std::iota(runs.begin(), runs.end(), 0u);
  return runs;
}

void SplatPass::run(FrameContext& frame, PointStore& store, const std::vector<C3rcData>& c3rcs,
                    const SplatItems& items) {
  const ivec2 size = frame.target.size();
  visibility_.begin(size_t(size.x) * size_t(size.y));
  if (counter_buffer_.size() == 0) counter_buffer_ = gpu::Buffer(sizeof(counters_));
  store.bind(MIRAGE_BIND_HYBRID_POINTS, MIRAGE_BIND_HYBRID_POINT_ATTRIBUTES);
  ms_ = 0.0;
  std::fill(std::begin(counters_), std::end(counters_), 0u);
  if (items.count == 0) return;

  c3rc_buffer_.upload(std::span<const C3rcData>(c3rcs));
  if (items.cpu) item_buffer_.upload(std::span<const ivec4>(*items.cpu));
  c3rc_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_C3RCS);
  (items.cpu ? item_buffer_ : *items.gpu)
      .bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_ITEMS);
  counter_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_COUNTERS);
  frame.target.depth().bind(MIRAGE_UNIT_HYBRID_DEPTH);
  const std::vector<uint32_t> item_runs = runs(items);
  run_buffer_.upload(std::span<const uint32_t>(item_runs));
  run_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_RUNS);
  const size_t run_count = item_runs.size() - 1;
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
    glDispatchCompute(GLuint(std::min<size_t>(run_count, 65535)), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    counter_buffer_.download(counters_, sizeof(counters_));
    candidates = counters_[MIRAGE_HYBRID_COUNTER_CANDIDATES];
  } while (!visibility_.fitted(candidates));
  visibility_.pickWinners(candidates);
  if (timing) {
    glFinish();
    ms_ = watch.ms();
  }
}

}  // namespace mirage
