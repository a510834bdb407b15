// Which of an object's depth maps a ray searches, shared by the depth-map shader and the C++
// tests. The impostor paper (§4.3) notes that more than one map is needed to capture an object
// (its Figure 13: a map of the bunny's front once the bunnies swap places) without saying how a
// ray chooses; a ray tries the maps in order of how nearly each camera looks along it, and
// falls back to the next when one misses: a surface the best-aligned camera does not see (hidden
// behind another part, or turned away from it) may face another.
//
// The includer defines, before including this file:
//   vec3 depthmap_axis(int map);  // the viewing direction of map `map` (world)
//   bool depthmap_try(int map);   // searches map `map` for the ray being traced: true on a hit
#ifndef MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_MAPS_SHARED_H
#define MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_MAPS_SHARED_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// Whether map a (its camera at cosine ca to the ray) comes before map b in the ray's order: the
// larger cosine first, ties to the lower index.
SHARED_FN bool depthmap_before(float ca, int a, float cb, int b) {
  return ca > cb || (ca == cb && a < b);
}

// The map that follows map `after` (-1: the first) among maps first .. first + count - 1 in the
// order a ray along `dir` tries them, or -1 when `after` was the last.
SHARED_FN int depthmap_next_map(vec3 dir, int first, int count, int after) {
  float after_cos = after >= 0 ? dot(dir, depthmap_axis(after)) : 0.0f;
  int best = -1;
  float best_cos = 0.0f;
  for (int k = first; k < first + count; ++k) {
    float c = dot(dir, depthmap_axis(k));
    bool later = after < 0 || depthmap_before(after_cos, after, c, k);
    if (later && (best < 0 || depthmap_before(c, k, best_cos, best))) {
      best = k;
      best_cos = c;
    }
  }
  return best;
}

// Searches an object's maps in the ray's order, at most `tries` of them (1: the best-aligned
// only), until one is hit. Returns the map hit, or -1.
SHARED_FN int depthmap_object_search(vec3 dir, int first, int count, int tries) {
  int map = -1;
  for (int attempt = 0; attempt < min(count, tries); ++attempt) {
    map = depthmap_next_map(dir, first, count, map);
    if (depthmap_try(map)) return map;
  }
  return -1;
}

SHARED_END

#endif  // MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_MAPS_SHARED_H
