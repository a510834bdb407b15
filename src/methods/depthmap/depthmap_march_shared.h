// The brute-force ray-depth-map intersection: walk the projected ray over the full depth map one
// texel step at a time (along its major axis) and take the first step from in front of a
// foreground texel to behind one — what the SRDMs replace (the impostor paper, §4.1: a ray
// projects to 91 texels on average, 63 of them examined). `--depthmap-search linear` runs it as
// the timed baseline. The includer defines, before including this file:
//   float depthmap_depth(int layer, int x, int y);  // window depth of texel (x, y); >= 1: none
#ifndef MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_MARCH_SHARED_H
#define MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_MARCH_SHARED_H

#include "shading/glsl_compat.h"

SHARED_BEGIN

// The first crossing along the projected ray from `from` to `to` (x, y texels, d depth) of map
// `layer` (w x w), as the fraction of the way, or -1; `examined` receives the texels read.
SHARED_FN float depthmap_march(int layer, int w, vec3 from, vec3 to, SHARED_OUT(int) examined) {
  float span = max(abs(to.x - from.x), abs(to.y - from.y));
  int steps = max(int(ceil(span)), 1);
  bool was_in_front = false;
  float prev_f = 0.0f, prev_u = 0.0f;
  examined = 0;
  for (int i = 0; i <= steps; ++i) {
    float u = float(i) / float(steps);
    vec3 p = from + (to - from) * u;
    int x = int(floor(p.x)), y = int(floor(p.y));
    bool inside = x >= 0 && y >= 0 && x < w && y < w;
    float d = 1.0f;
    if (inside) {
      d = depthmap_depth(layer, x, y);
      examined += 1;
    }
    float f = d - p.z;  // > 0: the ray is in front of the surface
    bool foreground = d < 1.0f;
    if (foreground && was_in_front && f <= 0.0f)
      return prev_u + (u - prev_u) * prev_f / max(prev_f - f, 1.0e-30f);
    was_in_front = foreground && f > 0.0f;
    prev_f = f;
    prev_u = u;
  }
  return -1.0f;
}

SHARED_END

#endif  // MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_MARCH_SHARED_H
