#include "methods/zexel/zexel_warp_pass.h"

#include <algorithm>

#include <tbb/task_arena.h>

#include "core/error.h"
#include "methods/zexel/zexel_camera.h"
#include "methods/zexel/zexel_cpu_warper.h"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"
#include "shading/shading.h"

namespace mirage {

void ZexelWarpTarget::resize(ivec2 size, const ZexelSplatOptions& splats, bool history) {
  // Grown, never shrunk: the mirror's rectangle changes every frame.
  const size_t cells = zexelCellCount(splats);
  if (cells > cells_count_) {
    keys_ = gpu::Buffer(cells * sizeof(uint32_t));
    cells_ = gpu::Buffer(cells * sizeof(uvec4));
    // The mirror reads them as texels (gpu::Texture::overBuffer says why).
    keys_texels_ = gpu::Texture::overBuffer(GL_R32UI, keys_);
    cells_texels_ = gpu::Texture::overBuffer(GL_RGBA32UI, cells_);
    cells_count_ = cells;
  }
  if (size != size_) history_ = gpu::Texture();
  if (history && history_.id() == 0) {
    history_ = gpu::Texture::create2D(GL_RGBA32F, size.x, size.y);
    const float unseen[4] = {0.0f, 0.0f, 0.0f, shading::MISS_DISTANCE};
    glClearTexImage(history_.id(), 0, GL_RGBA, GL_FLOAT, unseen);
  }
  size_ = size;
}

void ZexelWarpTarget::clear(size_t cells) const {
  const GLuint empty = MIRAGE_ZEXEL_EMPTY;
  glClearNamedBufferSubData(keys_.id(), GL_R32UI, 0, GLsizeiptr(cells * sizeof(uint32_t)),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
}

void ZexelWarpTarget::bindTexels() const {
  keys_texels_.bind(MIRAGE_UNIT_ZEXEL_KEYS);
  cells_texels_.bind(MIRAGE_UNIT_ZEXEL_CELLS);
  if (resolved_texels_.id() != 0) resolved_texels_.bind(MIRAGE_UNIT_ZEXEL_RESOLVED);
  if (history_.id() != 0)
    glBindImageTexture(MIRAGE_IMAGE_ZEXEL_HISTORY, history_.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                       GL_RGBA32F);
}

void ZexelWarpTarget::reserveResolved(const ivec4& rect) {
  // Grown, never shrunk, and only for a mirror the resolve pass serves.
  const size_t pixels = size_t(rect.z - rect.x) * size_t(rect.w - rect.y);
  if (pixels <= resolved_count_) return;
  resolved_ = gpu::Buffer(pixels * sizeof(vec4));
  resolved_texels_ = gpu::Texture::overBuffer(GL_RGBA32F, resolved_);
  resolved_count_ = pixels;
}

void ZexelWarpTarget::bindResolvedImage() const {
  glBindImageTexture(MIRAGE_IMAGE_ZEXEL_RESOLVED, resolved_texels_.id(), 0, GL_FALSE, 0,
                     GL_WRITE_ONLY, GL_RGBA32F);
}

void ZexelWarpTarget::bind() const {
  keys_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_KEYS);
  cells_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_CELLS);
  if (tiles_.id() != 0) tiles_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_TILES);
  if (history_.id() != 0)
    glBindImageTexture(MIRAGE_IMAGE_ZEXEL_HISTORY, history_.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                       GL_RGBA32F);
}

namespace {

WarpCamera outputCamera(const View& output) {
  return {zexelPixelMatrix(output, output.nearPlane()), output.eye()};
}

std::vector<ZexelWarpSource> sources(const ZexelWarpJob& job) {
  std::vector<ZexelWarpSource> s;
  for (int map : job.chosen)
    s.push_back({&job.maps->cpuMap(map, 0), job.maps->levels(), job.maps->width(0),
                 job.maps->warpCamera(map, 0)});
  return s;
}

}  // namespace

void planZexelJob(ZexelWarpJob& job, const View& output) {
  job.plans.clear();
  for (const ZexelWarpSource& s : sources(job))
    job.plans.push_back(planZexelTiles(s, outputCamera(output), job.splats));
}

void warpOnGpu(const gpu::Program& program, const ZexelWarpJob& job, const View& output,
               ZexelWarpTarget& target) {
  const ZexelSplatOptions& s = job.splats;
  // Every list of tiles in one buffer: slot after slot, level after level.
  std::vector<ZexelTileWord> words;
  for (const ZexelTilePlan& plan : job.plans)
    for (const auto& level : plan.by_level) words.insert(words.end(), level.begin(), level.end());
  if (!words.empty()) target.tiles().upload(std::span<const ZexelTileWord>(words));
  target.clear(zexelCellCount(s));
  target.bind();
  job.maps->texture().bind(MIRAGE_UNIT_ZEXEL_MAPS);
  program.set("u_width", job.maps->width(0));
  program.set("u_margin", zexelCellMargin(s));
  program.set("u_po_inverse", mat4(glm::inverse(outputCamera(output).p)));
  program.set("u_co", output.eye());
  program.set("u_splat", s.splat);
  program.set("u_pixel_scale", s.unit);
  program.set("u_rect", s.rect);
  program.use();
  for (int pass = 0; pass < 2; ++pass) {
    program.set("u_pass", pass);
    int first = 0;
    for (size_t slot = 0; slot < job.chosen.size(); ++slot) {
      const ZexelTilePlan& plan = job.plans[slot];
      const WarpCamera in = job.maps->warpCamera(job.chosen[slot], 0);
      program.set("u_layer", job.chosen[slot]);
      program.set("u_pi", mat4(in.p));
      program.set("u_ci", in.c);
      // Every level of the plan in one dispatch (a dispatch has a cost of its own: about 50 us
      // on llvmpipe with two threads): per level its zexels' end and its first tile.
      static_assert(shading::ZEXEL_TILE_SPAN + 1 == 4, "a plan's levels fill an ivec4");
      if (plan.by_level.size() > 4)
        throwRuntime("zexel: a tile plan of {} levels (at most 4)", plan.by_level.size());
      ivec4 ends(0), firsts(0);
      long zexels = 0;
      for (size_t l = 0; l < 4; ++l) {
        firsts[int(l)] = first;
        if (l < plan.by_level.size()) {
          const int count = int(plan.by_level[l].size());
          zexels += long(count) << (2 * (plan.tile_level - plan.finest - int(l)));
          first += count;
        }
        ends[int(l)] = int(zexels);
      }
      if (zexels == 0) continue;
      program.set("u_finest", plan.finest);
      program.set("u_tile_level", plan.tile_level);
      program.set("u_ends", ends);
      program.set("u_firsts", firsts);
      // An invocation per zexel, in rows of at most 65535 groups.
      const long groups = (zexels + MIRAGE_ZEXEL_GROUP - 1) / MIRAGE_ZEXEL_GROUP;
      const long row = std::min(groups, 65535L);
      glDispatchCompute(GLuint(row), GLuint((groups + row - 1) / row), 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
}

void warpOnCpu(const ZexelWarpJob& job, const View& output, int threads, ZexelWarpTarget& target) {
  ZexelCells cells;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    cells = warpZexels(sources(job), job.plans, outputCamera(output), job.splats, threads != 1);
  });
  std::vector<uint32_t> keys(cells.size());
  for (size_t i = 0; i < keys.size(); ++i) keys[i] = cells[i].x;
  target.keys().upload(std::span<const uint32_t>(keys));
  target.cells().upload(std::span<const uvec4>(cells));
  target.bind();
}

}  // namespace mirage
