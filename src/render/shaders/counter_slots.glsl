// A fragment's slot of the work counters (gpu/counter_slots_shared.h): the index of its first
// word in a buffer of MIRAGE_COUNTER_SLOTS * MIRAGE_COUNTER_SLOT_WORDS; counter k is at
// counter_slot() + k.
#include "gpu/counter_slots_shared.h"

int counter_slot() {
  ivec2 tile = ivec2(gl_FragCoord.xy) >> 6;
  return ((tile.x + 5 * tile.y) & (MIRAGE_COUNTER_SLOTS - 1)) * MIRAGE_COUNTER_SLOT_WORDS;
}
