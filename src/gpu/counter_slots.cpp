#include "gpu/counter_slots.h"

#include <array>

#include "core/check.h"

namespace mirage::gpu {

namespace {
using Words = std::array<GLuint, MIRAGE_COUNTER_SLOTS * MIRAGE_COUNTER_SLOT_WORDS>;
}

CounterSlots::CounterSlots(int counters) : counters_(counters) {
  MIRAGE_CHECK(counters > 0 && counters <= MIRAGE_COUNTER_SLOT_WORDS);
}

void CounterSlots::resetAndBind(GLuint binding) {
  const Words zeros{};
  buffer_.upload(std::span<const GLuint>(zeros));
  buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, binding);
  counted_ = true;
}

std::vector<double> CounterSlots::sums() const {
  std::vector<double> out(size_t(counters_), 0.0);
  if (!counted_) return out;
  Words words{};
  buffer_.download(words.data(), sizeof(words));
  for (int s = 0; s < MIRAGE_COUNTER_SLOTS; ++s)
    for (int k = 0; k < counters_; ++k)
      out[size_t(k)] += double(words[size_t(s * MIRAGE_COUNTER_SLOT_WORDS + k)]);
  return out;
}

}  // namespace mirage::gpu
