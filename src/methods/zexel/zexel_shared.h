// The zexel method's GPU data as the shaders and the C++ code see it: bindings, and the per-pixel
// words of the warp — the distance of the nearest zexel that landed (its float bits, which order
// like the floats for positive values, so atomicMin keeps the nearest) and which zexel that was.
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_SHARED_H

#include "shading/glsl_compat.h"

#define MIRAGE_BIND_ZEXEL_KEYS 4        // uint per pixel: the nearest landed distance's bits
#define MIRAGE_BIND_ZEXEL_INDICES 5     // uint per pixel: the zexel shown (slot bit 31, index)
#define MIRAGE_BIND_ZEXEL_COUNTERS 6    // uint[2]: mirror pixels shaded, exposed among them
#define MIRAGE_UNIT_ZEXEL_MAPS 4        // sampler2DArray: every map of the mirror, mip levels
#define MIRAGE_IMAGE_ZEXEL_HISTORY 0    // rgba32f: the mirror's last image (the no-clear option)
#define MIRAGE_IMAGE_ZEXEL_LEVEL_IN 1   // the pyramid build: the finer level
#define MIRAGE_IMAGE_ZEXEL_LEVEL_OUT 2  // ... and the coarser one it writes

#define MIRAGE_ZEXEL_GROUP 64              // invocations per warp work group (one zexel each)
#define MIRAGE_ZEXEL_MAX_SPLAT 8           // the largest magnification-sized splat, in pixels
#define MIRAGE_ZEXEL_EMPTY 0xFFFFFFFFu     // a pixel no zexel reached (an exposure)
#define MIRAGE_ZEXEL_SLOT_BIT 0x80000000u  // the second map of the frame

SHARED_BEGIN

// A zexel's index word: its map slot this frame (0 or 1) and its index in that map's level.
SHARED_FN uint zexel_index_word(int slot, uint index) {
  return slot == 0 ? index : (index | MIRAGE_ZEXEL_SLOT_BIT);
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_SHARED_H
