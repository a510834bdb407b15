// A fragment shader's work counters in slots (counter_slots_shared.h): zeroed and bound before
// a draw, summed over the slots after it.
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/counter_slots_shared.h"

namespace mirage::gpu {

class CounterSlots {
 public:
  // `counters` counters (at most MIRAGE_COUNTER_SLOT_WORDS).
  explicit CounterSlots(int counters);
  // Zeroes every slot and binds the buffer to storage-buffer `binding`.
  void resetAndBind(GLuint binding);
  // Each counter summed over the slots; zeros before the first resetAndBind. The draws that
  // count must be followed by glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT).
  std::vector<double> sums() const;
  // Whether a draw has counted into them yet (resetAndBind called).
  bool counted() const { return counted_; }

 private:
  int counters_;
  bool counted_ = false;
  Buffer buffer_;
};

}  // namespace mirage::gpu
