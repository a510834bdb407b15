// The per-row arithmetic of the SRDM builders (the impostor paper, §4.1-4.2), one copy for the
// C++ builder (srdm.cpp) and the compute shader (srdm_build.comp): where a row's samples lie and
// which texels they read, the relative z error, and the depth of a segment at a sample. Both
// builders call these so that they read the same texels and compare the same errors bit for bit;
// the greedy then makes the same choices (ties broken alike, see srdm_segment_above).
//
// The domain's direction a = (cos theta, sin theta) and extent E are inputs, computed once on the
// CPU for both: GLSL's cos/sin differ from the C library's in the last bits, which moves samples
// that fall on a texel edge into the neighbouring texel. Results that feed a later rounding are
// SRDM_EXACT (GLSL `precise`): a driver must not fuse their multiply-adds, which C++ (no -mfma)
// does not either.
#ifndef MIRAGE_METHODS_DEPTHMAP_SRDM_BUILD_SHARED_H
#define MIRAGE_METHODS_DEPTHMAP_SRDM_BUILD_SHARED_H

#include "shading/glsl_compat.h"

#ifdef MIRAGE_GLSL
#define SRDM_EXACT precise
#else
#define SRDM_EXACT
#endif

// The GPU builder's bindings (srdm_gpu_builder.cpp, srdm_build.comp): clear of the scene's
// shared ones (shading/gpu_types.h: SSBOs 1, 2, units 0-2) and of the methods' (SSBOs 4-7, units
// 4-10), so that a build between a method's binds and its draws disturbs neither.
#define SRDM_BUILD_DEPTH_UNIT 15   // sampler: the depth map
#define SRDM_BUILD_OUT_IMAGE 0     // image: the SRDM array being written
#define SRDM_BUILD_DOMAINS_SSBO 0  // vec4 per domain: cos, sin, extent, spacing
#define SRDM_BUILD_STATE_SSBO 3    // the foreground box and the dropped-sample count
#define SRDM_BUILD_ROWS_PER_GROUP 64
#define SRDM_BUILD_BOX_GROUP 16

SHARED_BEGIN

// The number of samples along a row of extent E: spacing E / count <= 1 texel.
SHARED_FN int srdm_sample_count(float extent) {
  return max(int(ceil(extent - 1.0e-4f)), 1);
}

// The texel-space point where row `row` starts (s = 0): srdm_from_domain((0, t_row)) with the
// direction given.
SHARED_FN vec2 srdm_row_start(vec2 a, float extent, int row, float w) {
  SRDM_EXACT float t = (float(row) + 0.5f) * extent / w - 0.5f * extent;
  vec2 b = vec2(-a.y, a.x);
  SRDM_EXACT vec2 start = vec2(0.5f * w) + (0.0f - 0.5f * extent) * a + t * b;
  return start;
}

// One slab of the clipping of a row (start + s dir, one axis) to [lo, hi]: narrows [s_in, s_out]
// (s_out = -1 when the row runs along the slab outside it).
SHARED_FN void srdm_clip_slab(float start, float dir, float lo, float hi, SHARED_INOUT(float) s_in,
                              SHARED_INOUT(float) s_out) {
  if (abs(dir) < 1.0e-7f) {
    if (start < lo || start > hi) s_out = -1.0f;
    return;
  }
  SRDM_EXACT float t0 = (lo - start) / dir;
  SRDM_EXACT float t1 = (hi - start) / dir;
  s_in = max(s_in, min(t0, t1));
  s_out = min(s_out, max(t0, t1));
}

// The samples k0..k1 of a row that lie over the foreground's bounding box (x0, y0, x1, y1), as
// ivec2(k0, k1); k1 < k0 when the row misses the box. The rest of the row is background.
SHARED_FN ivec2 srdm_row_range(vec2 start, vec2 a, ivec4 box, float extent, float spacing,
                               int count) {
  float s_in = 0.0f;
  float s_out = extent;
  srdm_clip_slab(start.x, a.x, float(box.x), float(box.z), s_in, s_out);
  srdm_clip_slab(start.y, a.y, float(box.y), float(box.w), s_in, s_out);
  if (s_in > s_out) return ivec2(0, -1);
  SRDM_EXACT float k0 = floor(s_in / spacing - 0.5f);
  SRDM_EXACT float k1 = ceil(s_out / spacing - 0.5f);
  return ivec2(max(int(k0), 0), min(int(k1), count - 1));
}

// Sample k of a row: its position s along the row and the texel it reads (nearest: depth is never
// blended across a silhouette).
SHARED_FN float srdm_sample_s(int k, float spacing) {
  SRDM_EXACT float s = (float(k) + 0.5f) * spacing;
  return s;
}
SHARED_FN ivec2 srdm_sample_texel(vec2 start, vec2 a, float s) {
  SRDM_EXACT vec2 p = start + s * a;
  return ivec2(floor(p));
}

// Relative eye-depth error of depth d_approx where the truth is d, k = (far - near) / far: with
// z = n f / (f - d (f - n)), |z' - z| / z = k |d' - d| / (1 - k d').
SHARED_FN float srdm_relative_z(float k, float d_approx, float d) {
  SRDM_EXACT float e = k * abs(d_approx - d) / max(1.0f - k * d_approx, 1.0e-12f);
  return e;
}

// A segment from knot (s0, d0) to a knot of depth d1, inv = srdm_segment_inverse(s0, s1): its
// depth at s.
SHARED_FN float srdm_segment_inverse(float s0, float s1) {
  SRDM_EXACT float inv = 1.0f / (s1 - s0);
  return inv;
}
SHARED_FN float srdm_segment_depth(float s0, float d0, float d1, float inv, float s) {
  SRDM_EXACT float d = d0 + (d1 - d0) * (s - s0) * inv;
  return d;
}

// The greedy's order of segments: the larger error first; equal errors, the segment whose worst
// sample comes first along the row (worst samples of segments with errors > 0 are distinct), so
// that both builders split the same segment whatever their queues' internal order.
SHARED_FN bool srdm_segment_above(float error_a, int worst_a, float error_b, int worst_b) {
  return error_a > error_b || (error_a == error_b && worst_a < worst_b);
}

SHARED_END

#endif  // MIRAGE_METHODS_DEPTHMAP_SRDM_BUILD_SHARED_H
