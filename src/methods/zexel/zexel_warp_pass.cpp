#include "methods/zexel/zexel_warp_pass.h"

#include <bit>

#include <tbb/task_arena.h>

#include "methods/zexel/zexel_camera.h"
#include "methods/zexel/zexel_shared.h"
#include "shading/shading.h"

namespace mirage {

void ZexelWarpTarget::resize(ivec2 size, bool history) {
  const size_t bytes = size_t(size.x) * size_t(size.y) * sizeof(uint32_t);
  if (size != size_) {
    keys_ = gpu::Buffer(bytes);
    indices_ = gpu::Buffer(bytes);
    history_ = gpu::Texture();
  }
  if (history && history_.id() == 0) {
    history_ = gpu::Texture::create2D(GL_RGBA32F, size.x, size.y);
    const float unseen[4] = {0.0f, 0.0f, 0.0f, shading::MISS_DISTANCE};
    glClearTexImage(history_.id(), 0, GL_RGBA, GL_FLOAT, unseen);
  }
  size_ = size;
}

void ZexelWarpTarget::clear() const {
  const GLuint empty = MIRAGE_ZEXEL_EMPTY;
  for (const gpu::Buffer* b : {&keys_, &indices_})
    glClearNamedBufferData(b->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
}

void ZexelWarpTarget::bind() const {
  keys_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_KEYS);
  indices_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_INDICES);
  if (history_.id() != 0)
    glBindImageTexture(MIRAGE_IMAGE_ZEXEL_HISTORY, history_.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                       GL_RGBA32F);
}

void warpOnGpu(const gpu::Program& program, const ZexelWarpJob& job, const View& output,
               ZexelWarpTarget& target) {
  target.clear();
  target.bind();
  job.maps->texture().bind(MIRAGE_UNIT_ZEXEL_MAPS);
  const int width = job.maps->width(job.level);
  program.set("u_level", job.level);
  program.set("u_width", width);
  program.set("u_po_inverse", mat4(glm::inverse(zexelPixelMatrix(output, output.nearPlane()))));
  program.set("u_co", output.eye());
  program.set("u_size", output.size());
  program.set("u_splat", job.splat);
  program.set("u_pixel_scale", job.pixel_scale);
  program.set("u_rect", job.rect);
  program.use();
  const GLuint groups = GLuint((width + 7) / 8);
  for (int pass = 0; pass < 2; ++pass) {
    program.set("u_pass", pass);
    for (size_t slot = 0; slot < job.chosen.size(); ++slot) {
      const WarpCamera in = job.maps->warpCamera(job.chosen[slot], job.level);
      program.set("u_slot", int(slot));
      program.set("u_layer", job.chosen[slot]);
      program.set("u_pi", mat4(in.p));
      program.set("u_ci", in.c);
      glDispatchCompute(groups, groups, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
}

long warpOnCpu(const ZexelWarpJob& job, const View& output, int threads, ZexelWarpTarget& target) {
  const ivec2 size = output.size();
  const WarpCamera out{zexelPixelMatrix(output, output.nearPlane()), output.eye()};
  std::vector<uint32_t> keys(size_t(size.x) * size_t(size.y), MIRAGE_ZEXEL_EMPTY);
  std::vector<uint32_t> words(keys.size(), MIRAGE_ZEXEL_EMPTY);
  long warped = 0;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  for (size_t slot = 0; slot < job.chosen.size(); ++slot) {
    const ZexelMap2D& map = job.maps->cpuMap(job.chosen[slot], job.level);
    const WarpCamera in = job.maps->warpCamera(job.chosen[slot], job.level);
    std::vector<uint32_t> shown;
    arena.execute([&] {
      shown = warpOcclusionCompatible(map, in, out, size,
                                      {.splat = job.splat,
                                       .parallel = threads != 1,
                                       .rect = job.rect,
                                       .unit = job.pixel_scale});
    });
    warped += long(map.width) * map.height;
    // The second map fills what the first left and wins where it saw something nearer.
    for (size_t p = 0; p < shown.size(); ++p) {
      if (shown[p] == kNoZexel) continue;
      const uint32_t key = std::bit_cast<uint32_t>(zexelDistance(map, in, shown[p], out.c));
      if (key < keys[p]) {
        keys[p] = key;
        words[p] = shading::zexel_index_word(int(slot), shown[p]);
      }
    }
  }
  target.keys().upload(std::span<const uint32_t>(keys));
  target.indices().upload(std::span<const uint32_t>(words));
  target.bind();
  return warped;
}

}  // namespace mirage
