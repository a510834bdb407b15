#include "methods/hybrid/splat_visibility.h"

#include <algorithm>

#include "core/error.h"
#include "methods/hybrid/hybrid_shared.h"

namespace mirage {

namespace {

// Pixel, depth key, winner word (hybrid_winner_word), and a word to keep records 16 bytes.
constexpr size_t kRecord = 4 * sizeof(uint32_t);

// Bytes for `count` candidates, within the driver's largest storage block.
size_t candidateBytes(size_t count) {
  GLint64 largest = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
  return std::max<size_t>(std::min(count, size_t(largest) / kRecord), 1) * kRecord;
}

}  // namespace

SplatVisibility::SplatVisibility()
    : winner_program_(gpu::Program::compute("methods/hybrid/hybrid_winner.comp")) {}

void SplatVisibility::clearWords(gpu::Buffer& buffer, uint32_t value) {
  glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

void SplatVisibility::begin(size_t pixels) {
  if (pixels_ != pixels) {
    depths_ = gpu::Buffer(pixels * sizeof(uint32_t));
    winners_ = gpu::Buffer(pixels * sizeof(uint32_t));
    pixels_ = pixels;
  }
  // One record a pixel to start with; a frame that appends more grows it (fitted).
  if (candidates_.size() == 0) candidates_ = gpu::Buffer(candidateBytes(pixels));
  clearWords(winners_, MIRAGE_HYBRID_EMPTY);
  depths_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_SPLATS);
  winners_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_WINNERS);
}

size_t SplatVisibility::prepare() {
  clearWords(depths_, MIRAGE_HYBRID_EMPTY);
  candidates_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_HYBRID_CANDIDATES);
  return candidates_.size() / kRecord;
}

bool SplatVisibility::fitted(size_t count) {
  if (count <= candidates_.size() / kRecord) return true;
  if (candidateBytes(count) < count * kRecord)
    throwRuntime(
        "hybrid: {} splat candidates are more than the GL driver's largest storage block holds "
        "({} MiB): lower --size, --ssaa or --points",
        count, candidateBytes(count) >> 20);
  candidates_ = gpu::Buffer(candidateBytes(count + count / 4));  // a quarter to spare
  return false;
}

void SplatVisibility::pickWinners(size_t count) {
  if (count == 0) return;
  const size_t groups = (count + MIRAGE_HYBRID_WINNER_GROUP - 1) / MIRAGE_HYBRID_WINNER_GROUP;
  const size_t x = std::min<size_t>(groups, 65535), y = (groups + x - 1) / x;
  winner_program_.set("u_candidate_count", int(count));
  winner_program_.use();
  glDispatchCompute(GLuint(x), GLuint(y), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace mirage
