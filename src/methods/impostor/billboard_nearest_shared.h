// The alpha-tested nearest hit over a list of billboards (the impostor paper, §3.1, step 2),
// shared by billboard.frag and the C++ tests. It reads billboards through three functions that
// the includer defines before including this header (GLSL: storage buffers and textures; C++
// tests: vectors, in namespace mirage::shading):
//   BillboardData billboard_data(int index);             // a billboard
//   int billboard_list_entry(int position);              // the billboard index at `position`
//   float billboard_coverage(BillboardData b, vec2 uv);  // alpha at level 0, in [0, 1]
#ifndef MIRAGE_METHODS_IMPOSTOR_BILLBOARD_NEAREST_SHARED_H
#define MIRAGE_METHODS_IMPOSTOR_BILLBOARD_NEAREST_SHARED_H

#include "methods/impostor/billboard_shared.h"

SHARED_BEGIN

// The nearest billboard among list entries [first, first + count) that the ray hits at
// t_min < t < t_best where its coverage passes the alpha test. Returns its index and lowers
// t_best and sets uv, or returns -1 and leaves them.
SHARED_FN int nearest_billboard(vec3 origin, vec3 dir, int first, int count, float t_min,
                                SHARED_INOUT(float) t_best, SHARED_INOUT(vec2) uv) {
  int best = -1;
  for (int k = first; k < first + count; ++k) {
    int index = billboard_list_entry(k);
    BillboardData b = billboard_data(index);
    vec2 hit_uv = vec2(0.0f);
    float t = billboard_hit(b, origin, dir, t_min, hit_uv);
    if (t < 0.0f || t >= t_best) continue;
    if (billboard_coverage(b, hit_uv) < MIRAGE_BILLBOARD_ALPHA_CUTOFF) continue;
    best = index;
    t_best = t;
    uv = hit_uv;
  }
  return best;
}

SHARED_END

#endif  // MIRAGE_METHODS_IMPOSTOR_BILLBOARD_NEAREST_SHARED_H
