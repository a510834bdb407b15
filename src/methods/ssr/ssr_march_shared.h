// Method `ssr`: the reflected ray's march through the hierarchical-Z pyramid of the depth
// buffer, shared by the reflection shader and the tests (which run it against a brute-force
// march over every pixel). The includer defines, before including this file:
//   vec2 ssr_cell(int level, int x, int y);  // cell (x, y) of `level` (level 0: the depth
//                                            // buffer): x its nearest window depth (1: nothing
//                                            // drawn), y the behind limit of its farthest drawn
//                                            // depth (ssr_depth_shared.h; 0: nothing drawn)
//
// The ray is a segment in screen space: x, y in window pixels (bottom-left origin, as
// gl_FragCoord and the pyramid's texels), z the window depth, which is affine in screen space along
// a projected line — so the march steps in 2D and reads z linearly. Level l of the pyramid has
// cells of 2^l pixels, each the minimum of the (up to) four cells below it. A cell is skipped whole
// when the ray's deepest point inside it is still in front of the cell's nearest depth, or when
// its nearest point is behind the cell's farthest drawn depth by more than the thickness (it
// passes behind everything there): nothing in it can be hit, and the march climbs a level;
// otherwise it descends, down to single pixels, where the hit test is made. It finds the first
// pixel along the ray that passes that test — the same pixel a march over every pixel finds — in
// O(log) steps over empty stretches. A step reads one texel and makes no division (llvmpipe runs
// every lane of a step for as long as any lane of its group marches).
#ifndef MIRAGE_METHODS_SSR_SSR_MARCH_SHARED_H
#define MIRAGE_METHODS_SSR_SSR_MARCH_SHARED_H

#include "methods/ssr/ssr_depth_shared.h"

SHARED_BEGIN

// The pixel test: the ray crosses pixel `p` with window depth za on entry and zb on exit, the
// depth buffer holds d there and `limit` is d's behind limit (ssr_behind_limit). A hit when the
// ray reaches the surface inside the pixel: it enters in front and leaves behind (crossing it),
// or enters behind by no more than the thickness — a surface is taken to be that thick, so that
// a ray passing far behind a foreground object is not stopped by it. d >= 1: nothing drawn.
SHARED_FN bool ssr_pixel_hit(float za, float zb, float d, float limit) {
  return d < 1.0f && max(za, zb) >= d && za <= limit;
}

// A ray's cell exits, prepared once a ray: a cell's exit along an axis is (its far edge − from) /
// d, the edge cell · (corner + ahead), so it is edge · inv + offset; an axis the ray does not
// move along never ends it (its parameter 2, past the end). No division per cell.
SHARED_FN void ssr_exit_setup(vec3 from, vec3 to, SHARED_OUT(vec2) ahead, SHARED_OUT(vec2) inv,
                              SHARED_OUT(vec2) offset) {
  vec2 d = vec2(to.x - from.x, to.y - from.y);
  ahead = vec2(d.x > 0.0f ? 1.0f : 0.0f, d.y > 0.0f ? 1.0f : 0.0f);
  inv = vec2(d.x != 0.0f ? 1.0f / d.x : 0.0f, d.y != 0.0f ? 1.0f / d.y : 0.0f);
  offset = vec2(d.x != 0.0f ? -from.x * inv.x : 2.0f, d.y != 0.0f ? -from.y * inv.y : 2.0f);
}

// The parameter along from -> to where the ray leaves the cell of size `cell` holding the point
// at parameter t (clamped to 1), from its prepared exits; `corner` receives the cell.
SHARED_FN float ssr_exit_from(vec3 from, vec3 to, vec2 ahead, vec2 inv, vec2 offset, float t,
                              float cell, SHARED_OUT(vec2) corner) {
  vec2 d = vec2(to.x - from.x, to.y - from.y);
  corner = floor((vec2(from.x, from.y) + t * d) * (1.0f / cell));
  vec2 exits = (corner + ahead) * cell * inv + offset;
  return max(min(min(exits.x, exits.y), 1.0f), t);
}

// The same for one cell of a ray.
SHARED_FN float ssr_cell_exit(vec3 from, vec3 to, float t, float cell) {
  vec2 ahead, inv, offset, corner;
  ssr_exit_setup(from, to, ahead, inv, offset);
  return ssr_exit_from(from, to, ahead, inv, offset, t, cell, corner);
}

// A small step past a cell boundary, in parameter units: 1/1024 pixel along the major axis.
SHARED_FN float ssr_nudge(vec3 from, vec3 to) {
  return (1.0f / 1024.0f) / max(max(abs(to.x - from.x), abs(to.y - from.y)), 1.0e-6f);
}

// Marches from -> to (already clipped to the screen, from at the reflecting pixel) through a
// pyramid of `levels` levels. Returns the parameter of the hit pixel's entry point (>= 0) or -1
// (no hit before `to`, or more than `max_steps` cells visited); `hit_pixel` receives the hit
// pixel, `steps` the cells visited. The reflecting pixel itself is never tested.
SHARED_FN float ssr_march(vec3 from, vec3 to, int levels, int max_steps,
                          SHARED_OUT(ivec2) hit_pixel, SHARED_OUT(int) steps) {
  vec2 ahead, inv, offset, corner;
  ssr_exit_setup(from, to, ahead, inv, offset);
  float nudge = ssr_nudge(from, to);
  float t = ssr_exit_from(from, to, ahead, inv, offset, 0.0f, 1.0f, corner) + nudge;
  int level = 0;
  steps = 0;
  hit_pixel = ivec2(-1, -1);
  while (t < 1.0f && steps < max_steps) {
    steps += 1;
    float exit_t = ssr_exit_from(from, to, ahead, inv, offset, t, float(1 << level), corner);
    ivec2 c = ivec2(corner);
    float za = from.z + t * (to.z - from.z);
    float zb = from.z + exit_t * (to.z - from.z);
    vec2 here = ssr_cell(level, c.x, c.y);
    if (max(za, zb) < here.x || min(za, zb) > here.y) {
      // Nothing in this cell is as near as the ray gets, or the ray passes behind all of it by
      // more than the thickness: skip it and try a coarser cell.
      t = exit_t + nudge;
      if (level + 1 < levels) level += 1;
    } else if (level > 0) {
      level -= 1;
    } else {
      if (ssr_pixel_hit(za, zb, here.x, here.y)) {
        hit_pixel = c;
        return t;
      }
      t = exit_t + nudge;
    }
  }
  return -1.0f;
}

// Binary refinement of a hit: the pixel test is made on whole pixels; within the hit pixel (the
// ray between parameters t0 and t1) bisect for where the ray meets the depth buffer's bilinear
// interpolation, so the colour is read where the surface is rather than at the pixel's edge.
// The depth buffer interpolated bilinearly between pixel centres (clamped to `size`).
SHARED_FN float ssr_bilinear_depth(vec2 p, ivec2 size) {
  vec2 q = p - vec2(0.5f, 0.5f);
  vec2 base = floor(q);
  vec2 f = q - base;
  int x0 = clamp(int(base.x), 0, size.x - 1), x1 = clamp(int(base.x) + 1, 0, size.x - 1);
  int y0 = clamp(int(base.y), 0, size.y - 1), y1 = clamp(int(base.y) + 1, 0, size.y - 1);
  float a = ssr_cell(0, x0, y0).x, b = ssr_cell(0, x1, y0).x;
  float c = ssr_cell(0, x0, y1).x, d = ssr_cell(0, x1, y1).x;
  return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

SHARED_FN float ssr_refine(vec3 from, vec3 to, float t0, float t1, ivec2 size, int iterations) {
  float lo = t0, hi = t1;
  for (int i = 0; i < iterations; ++i) {
    float mid = 0.5f * (lo + hi);
    vec3 p = from + mid * (to - from);
    if (p.z >= ssr_bilinear_depth(vec2(p.x, p.y), size))
      hi = mid;
    else
      lo = mid;
  }
  return hi;
}

SHARED_END

#endif  // MIRAGE_METHODS_SSR_SSR_MARCH_SHARED_H
