#include "methods/depthmap/srdm_gpu_builder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "gpu/loop_budget.h"
#include "methods/depthmap/srdm_build_shared.h"
#include "methods/depthmap/srdm_shared.h"

namespace mirage {

namespace sh = shading;

namespace {

constexpr const char* kShader = "methods/depthmap/srdm_build.comp";

// The State block of srdm_build.comp (std430).
struct BuildState {
  ivec4 box;
  int dropped = 0;
  int pad[3] = {0, 0, 0};
};
static_assert(sizeof(BuildState) == 32);

}  // namespace

SrdmGpuBuilder::SrdmGpuBuilder()
    : box_(gpu::Program::compute(kShader, {"SRDM_PASS_BOX"})), state_(sizeof(BuildState)) {}

const gpu::Program& SrdmGpuBuilder::rowProgram(int points) {
  // The smallest capacity that holds m points: a row's private arrays stay small for small m.
  int index = 0;
  while ((8 << index) < points) ++index;
  gpu::Program& program = rows_[index];
  if (!program)
    program = gpu::Program::compute(
        kShader, {"SRDM_PASS_ROWS", "SRDM_MAX_POINTS " + std::to_string(8 << index)});
  return program;
}

long long SrdmGpuBuilder::rowLoopCost(int samples, int m) {
  using gpu::loopCost;
  const long long n = samples, k = m / 2, h = std::bit_width(unsigned(std::max(m, 1)));
  const long long scan = loopCost(n + 1, loopCost(k) + loopCost(k - 1));  // offer_span's two
  const long long knots = loopCost(k);
  const long long worst_of = loopCost(n), heap = loopCost(h);
  const long long queue = loopCost(k, worst_of + heap);
  const long long refine = loopCost(std::max(m - 2, 0), 2 * worst_of + 2 * heap);
  const long long emit = loopCost(k, loopCost(m)) + loopCost(m + 1LL);
  return scan + knots + queue + refine + emit;
}

gpu::Texture SrdmGpuBuilder::createOutput(int size, const SrdmSettings& settings) {
  return gpu::Texture::create2DArray(GL_RGBA32F, (settings.points + 1) / 2, size, settings.domains);
}

void SrdmGpuBuilder::build(const gpu::Texture& depth, float near, float far,
                           const SrdmSettings& settings, gpu::Texture& out) {
  const int w = depth.size().x;
  checkSrdmSettings(w, settings);
  if (settings.simplifier != SrdmSimplifier::kGreedy)
    throwInput("--srdm-simplify {}: the GPU SRDM builder supports only 'greedy'",
               srdmSimplifierName(settings.simplifier));
  if (depth.target() != GL_TEXTURE_2D || depth.size().y != w ||
      (depth.internalFormat() != GL_R32F && depth.internalFormat() != GL_DEPTH_COMPONENT32F))
    throwRuntime(
        "SRDM GPU builder: the depth map must be a square R32F or DEPTH_COMPONENT32F 2D "
        "texture");
  const int n = settings.domains, m = settings.points, pairs = (m + 1) / 2;
  if (out.target() != GL_TEXTURE_2D_ARRAY || out.internalFormat() != GL_RGBA32F ||
      out.size() != ivec2(pairs, w) || out.layers() != n)
    throwRuntime("SRDM GPU builder: the output must be an RGBA32F {}x{} array of {} layers", pairs,
                 w, n);

  // The domains' directions and sample spacings, computed here for both builders (see shared).
  if (domain_count_ != n || domain_size_ != w) {
    std::vector<vec4> geometry(static_cast<size_t>(n));
    int most_samples = 0;
    for (int i = 0; i < n; ++i) {
      const float theta = sh::srdm_theta(i, n);
      const float extent = sh::srdm_extent(theta, float(w));
      const int samples = sh::srdm_sample_count(extent);
      const float spacing = extent / float(samples);
      geometry[size_t(i)] = vec4(std::cos(theta), std::sin(theta), extent, spacing);
      most_samples = std::max(most_samples, samples);
    }
    gpu::checkLoopBudget(fmt::format("the SRDM GPU builder (--depthmap-size {}, --srdm-m {})", w, m),
                         rowLoopCost(most_samples, m));
    domains_ = gpu::Buffer::fromSpan(std::span<const vec4>(geometry));
    domain_count_ = n;
    domain_size_ = w;
  }
  BuildState initial;
  initial.box = ivec4(w, w, 0, 0);
  state_.uploadValue(initial);

  depth.bind(SRDM_BUILD_DEPTH_UNIT);
  state_.bindBase(GL_SHADER_STORAGE_BUFFER, SRDM_BUILD_STATE_SSBO);
  box_.set("u_size", w);
  box_.use();
  const GLuint box_groups = GLuint((w + SRDM_BUILD_BOX_GROUP - 1) / SRDM_BUILD_BOX_GROUP);
  glDispatchCompute(box_groups, box_groups, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  // Rows: one invocation each, a group for 64 rows of a domain.
  const gpu::Program& rows = rowProgram(m);
  domains_.bindBase(GL_SHADER_STORAGE_BUFFER, SRDM_BUILD_DOMAINS_SSBO);
  glBindImageTexture(SRDM_BUILD_OUT_IMAGE, out.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  rows.set("u_size", w);
  rows.set("u_domains", n);
  rows.set("u_points", m);
  rows.set("u_k", (far - near) / far);  // as RelativeZ
  rows.use();
  glDispatchCompute(GLuint((w + SRDM_BUILD_ROWS_PER_GROUP - 1) / SRDM_BUILD_ROWS_PER_GROUP),
                    GLuint(n), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

int SrdmGpuBuilder::droppedSamples() const {
  BuildState state;
  state_.download(&state, sizeof(state));
  return state.dropped;
}

Srdm SrdmGpuBuilder::download(const gpu::Texture& out, int points) const {
  Srdm srdm;
  srdm.size = out.size().y;
  srdm.domains = out.layers();
  srdm.points = points;
  srdm.texels.resize(size_t(srdm.domains) * size_t(srdm.size) * size_t(srdm.pairs()));
  // Layers, then rows, then pairs: Srdm's order.
  glGetTextureImage(out.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(srdm.bytes()), srdm.texels.data());
  srdm.dropped_samples = droppedSamples();
  return srdm;
}

Srdm SrdmGpuBuilder::build(const DepthMap& map, const SrdmSettings& settings) {
  checkSrdmSettings(map.size, settings);
  const gpu::Texture depth = uploadDepthMap(map);
  gpu::Texture out = createOutput(map.size, settings);
  build(depth, map.near, map.far, settings, out);
  return download(out, settings.points);
}

gpu::Texture uploadDepthMap(const DepthMap& map) {
  gpu::Texture t = gpu::Texture::create2D(GL_R32F, map.size, map.size);
  t.setFilter(GL_NEAREST, GL_NEAREST);
  t.upload(0, GL_RED, GL_FLOAT, map.depth.data());
  return t;
}

}  // namespace mirage
