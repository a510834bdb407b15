// Work counters of a fragment shader, kept in slots: each slot on a cache line of its own, a
// pixel adding to the slot of its 64 x 64 tile. llvmpipe's threads shade different tiles, and
// atomics of two threads on one line stall both; a frame's count is the slots' sum
// (gpu/counter_slots.h on the C++ side, render/shaders/counter_slots.glsl in the shaders).
#ifndef MIRAGE_GPU_COUNTER_SLOTS_SHARED_H
#define MIRAGE_GPU_COUNTER_SLOTS_SHARED_H

#define MIRAGE_COUNTER_SLOTS 16
#define MIRAGE_COUNTER_SLOT_WORDS 16  // 64 bytes a slot: at most 16 counters

#endif  // MIRAGE_GPU_COUNTER_SLOTS_SHARED_H
