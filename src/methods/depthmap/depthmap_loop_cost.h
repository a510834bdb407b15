// The worst case of depthmap.frag's loops in the loop limiter's count (gpu/loop_budget.h): what
// the method's hooks add to each bounce of the impostor trace (impostorTraceLoopCost).
#pragma once

#include <algorithm>

#include "gpu/loop_budget.h"
#include "methods/depthmap/depthmap_shared.h"

namespace mirage {

// The worst case of one map's search in depthmap.frag (gpu/loop_budget.h): the frustum clip's
// six planes, then the search compiled in — SRDM rows of (m + 1) / 2 point pairs, the blend of
// two rows over 2m + 1 pieces, or the full map's walk of up to w + 1 steps.
inline long long mapSearchLoopCost(int search, int m, int w) {
  const long long clip = gpu::loopCost(6);
  const long long row = gpu::loopCost((m + 1) / 2, gpu::loopCost(2));
  const long long blend = gpu::loopCost(2LL * m + 1);
  switch (search) {
    case MIRAGE_DEPTHMAP_SEARCH_LINEAR: return clip + gpu::loopCost(w + 1LL);
    case MIRAGE_DEPTHMAP_SEARCH_HIT: return clip + 2 * row;
    case MIRAGE_DEPTHMAP_SEARCH_INTERPOLATE: return clip + 2 * row + blend;
    case MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE: return clip + 3 * row + blend;
    default: return clip + row;
  }
}

// What depthmap.frag's impostor_extra_hit costs a bounce: its loop over the `entries` objects
// of a list, each with up to `maps` maps tried `tries` times in the ray's order (the next-map
// scan and a search), and, with self maps, the `self_maps` searches of a reflector's own (the
// lanes of a batch may be in different lists: both sides run).
inline long long depthMapHookLoopCost(long long entries, int maps, int tries, int self_maps,
                               long long search) {
  const long long object =
      gpu::loopCost(std::min(maps, tries), gpu::loopCost(maps) + search);
  const long long self = self_maps > 0 ? gpu::loopCost(self_maps, search) : 0;
  return gpu::loopCost(entries, object + self);
}

}  // namespace mirage
