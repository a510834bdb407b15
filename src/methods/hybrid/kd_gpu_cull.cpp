#include "methods/hybrid/kd_gpu_cull.h"

#include <algorithm>
#include <utility>

#include <tbb/parallel_for.h>

#include "core/error.h"
#include "core/timer.h"
#include "methods/hybrid/c3rc.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/kd_gpu_shared.h"

namespace mirage {

namespace {

using shading::KdNodeGpu;

// The first item and queue buffers; they grow to fit the frames seen, and stay.
constexpr size_t kMinCapacity = 4096;
constexpr GLuint kMaxGroups = 65535;  // per dimension of a dispatch

int cullMode(Culling culling) {
  switch (culling) {
    case Culling::kNone:
      return MIRAGE_KD_CULL_NONE;
    case Culling::kHull:
      return MIRAGE_KD_CULL_HULL;
    case Culling::kInner:
      return MIRAGE_KD_CULL_INNER;
    case Culling::kExact:
      break;
  }
  return MIRAGE_KD_CULL_EXACT;
}

}  // namespace

KdGpuCull::KdGpuCull(const PointStore& store)
    : store_(store), program_(gpu::Program::compute("methods/hybrid/hybrid_cull.comp")) {
  std::vector<KdNodeGpu> flat;
  std::vector<uint32_t> roots;
  for (const PointCloud& cloud : store.clouds()) {
    const uint32_t base = uint32_t(flat.size());
    roots.push_back(cloud.tree.empty() ? MIRAGE_KD_NO_ROOT : base);
    for (size_t i = 0; i < cloud.tree.nodes().size(); ++i) {
      const KdNode& n = cloud.tree.nodes()[i];
      flat.push_back({vec4(n.bounds.lo, 0.0f), vec4(n.bounds.hi, 0.0f),
                      uvec4(cloud.offset + n.begin, cloud.offset + n.end,
                            n.leaf() ? 0u : base + n.first_child, n.child_count),
                      cloud.cones[i]});
    }
  }
  nodes_.upload(std::span<const KdNodeGpu>(flat));
  roots_.upload(std::span<const uint32_t>(roots));
  state_ = gpu::Buffer(MIRAGE_KD_STATE_SIZE * sizeof(uint32_t));
}

void KdGpuCull::reserve(gpu::Buffer& buffer, size_t& capacity, size_t count, size_t bytes) {
  if (count <= capacity && buffer.size() > 0) return;
  GLint64 largest = 0;  // the largest storage block a shader may address
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
  const size_t most = size_t(largest) / bytes;
  if (count > most)
    throwGpu(
        "hybrid GPU culling: {} entries exceed the driver's GL_MAX_SHADER_STORAGE_BLOCK_SIZE ({} "
        "bytes); use "
        "--hybrid-cull-on cpu (it merges leaves) or fewer points",
        count, largest);
  capacity = std::min(most, std::max({kMinCapacity, count + count / 4, capacity}));
  buffer = gpu::Buffer(capacity * bytes);
}

KdGpuCullResult KdGpuCull::run(const std::vector<C3rcData>& c3rcs,
                               const std::vector<mat4>& matrices, Culling culling,
                               bool cull_backfaces) {
  KdGpuCullResult result;
  const std::vector<PointCloud>& clouds = store_.clouds();
  const size_t n = clouds.size();
  if (c3rcs.empty() || n == 0) return result;

  // The query moves into each cloud's space, as on the CPU path (c3rc_frame.cpp) — with the same
  // calls, so that both paths test the same bits. transformC3rc rebuilds the hull and the
  // fold intervals (makeC3rc), which would be a second, array-heavy copy in GLSL.
  Stopwatch transform;
  std::vector<mat4> to_object;
  for (const PointCloud& c : clouds)
    to_object.push_back(glm::inverse(matrices[size_t(c.points.instance)]));
  local_.resize(c3rcs.size() * n);
  tbb::parallel_for(size_t(0), c3rcs.size(), [&](size_t i) {
    const bool degenerate = (int(c3rcs[i].info.z) & MIRAGE_C3RC_DEGENERATE) != 0;
    for (size_t k = 0; k < n; ++k)
      local_[i * n + k] = degenerate ? c3rcs[i] : transformC3rc(c3rcs[i], to_object[k]);
  });
  result.transform_ms = transform.ms();

  Stopwatch watch;
  c3rcs_.upload(std::span<const C3rcData>(local_));
  program_.set("u_cloud_count", int(n));
  program_.set("u_culling", cullMode(culling));
  program_.set("u_cull_backfaces", cull_backfaces ? 1 : 0);
  reserve(items_, item_capacity_, 0, sizeof(ivec4));
  reserve(queue_in_, in_capacity_, 0, sizeof(uvec2));
  reserve(queue_out_, out_capacity_, local_.size(), sizeof(uvec2));
  uint32_t state[MIRAGE_KD_STATE_SIZE] = {};
  size_t entries = local_.size();
  for (bool first = true; entries > 0; first = false) {
    // Never drop an entry: a level that counted more than a buffer holds grows it and reruns,
    // from the state words as they were before it.
    uint32_t next[MIRAGE_KD_STATE_SIZE];
    for (;;) {
      std::copy(state, state + MIRAGE_KD_STATE_SIZE, next);
      next[MIRAGE_KD_STATE_QUEUED] = 0;
      dispatchLevel(entries, first, next);
      ++result.dispatches;
      const size_t items = next[MIRAGE_KD_STATE_ITEMS], queued = next[MIRAGE_KD_STATE_QUEUED];
      if (items <= item_capacity_ && queued <= out_capacity_) break;
      if (items > item_capacity_) {
        // The items written so far move with the buffer.
        gpu::Buffer old = std::move(items_);
        reserve(items_, item_capacity_, items, sizeof(ivec4));
        const size_t kept = state[MIRAGE_KD_STATE_ITEMS];
        if (kept)
          glCopyNamedBufferSubData(old.id(), items_.id(), 0, 0, GLsizeiptr(kept * sizeof(ivec4)));
      }
      reserve(queue_out_, out_capacity_, queued, sizeof(uvec2));
    }
    std::copy(next, next + MIRAGE_KD_STATE_SIZE, state);
    entries = state[MIRAGE_KD_STATE_QUEUED];
    std::swap(queue_in_, queue_out_);
    std::swap(in_capacity_, out_capacity_);
    reserve(queue_out_, out_capacity_, entries, sizeof(uvec2));  // a guess: it grows if short
  }
  result.gpu_ms = watch.ms();
  result.items = state[MIRAGE_KD_STATE_ITEMS];
  result.points = state[MIRAGE_KD_STATE_POINTS];
  result.cull.nodes_tested = state[MIRAGE_KD_STATE_TESTED];
  result.cull.hull_rejects = state[MIRAGE_KD_STATE_HULL_REJECTS];
  result.cull.exact_rejects = state[MIRAGE_KD_STATE_EXACT_REJECTS];
  result.cull.fold_keeps = state[MIRAGE_KD_STATE_FOLD_KEEPS];
  result.cull.cone_rejects = state[MIRAGE_KD_STATE_CONE_REJECTS];
  result.cull.leaves_kept = state[MIRAGE_KD_STATE_ITEMS];
  return result;
}

void KdGpuCull::dispatchLevel(size_t entries, bool first_level, uint32_t* state) {
  state_.upload(state, MIRAGE_KD_STATE_SIZE * sizeof(uint32_t));
  program_.set("u_entry_count", int(entries));
  program_.set("u_first_level", first_level ? 1 : 0);
  program_.set("u_item_capacity", int(item_capacity_));
  program_.set("u_queue_capacity", int(out_capacity_));
  c3rcs_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_C3RCS);
  nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_KD_NODES);
  roots_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_KD_ROOTS);
  queue_in_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_KD_QUEUE_IN);
  queue_out_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_KD_QUEUE_OUT);
  items_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_ITEMS);
  state_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_KD_STATE);
  program_.use();
  const size_t groups = (entries + MIRAGE_KD_CULL_GROUP - 1) / MIRAGE_KD_CULL_GROUP;
  const GLuint x = GLuint(std::min<size_t>(groups, kMaxGroups));
  glDispatchCompute(x, GLuint((groups + x - 1) / x), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  // The wall time of the culling includes its completion (GL timer queries lie on llvmpipe);
  // the read-back would wait for it anyway, and the next level's size and the capacity checks
  // need the counts.
  glFinish();
  state_.download(state, MIRAGE_KD_STATE_SIZE * sizeof(uint32_t));
}

std::vector<ivec4> KdGpuCull::downloadItems(size_t count) const {
  std::vector<ivec4> out(count);
  if (count) items_.download(out.data(), count * sizeof(ivec4));
  return out;
}

}  // namespace mirage
