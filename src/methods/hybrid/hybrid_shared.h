// The hybrid method's data as the shaders and the C++ code see it: the point samples, the work
// items of the splatting pass, and the per-pixel visibility — the point nearest the reflector
// wins (the push-back distance: the paper's rule), ties to the lowest index. GL 4.5 has no
// 64-bit atomics (llvmpipe neither), and a 32-bit word holding both leaves the depth 10 bits at
// 4M points (22 for the index): so the splatting pass keeps the nearest push-back per pixel, all
// 32 bits of it, with atomicMin, and appends each splat that was at least as near as its pixel's
// word then (the candidates); a second pass gives each pixel the lowest index among its
// candidates at the final depth (hybrid_winner.comp).
#ifndef MIRAGE_METHODS_HYBRID_HYBRID_SHARED_H
#define MIRAGE_METHODS_HYBRID_HYBRID_SHARED_H

#include "shading/glsl_compat.h"

// Storage bindings (the method's SSBO slot and after) and texture units.
#define MIRAGE_BIND_HYBRID_C3RCS 4  // C3rcData[]
#define MIRAGE_BIND_HYBRID_ITEMS 5  // ivec4 work items: C3RC, first point, count, unused
#define MIRAGE_BIND_HYBRID_POINTS \
  6  // vec4[]: every set's positions in leaf order (PointAttributes)
#define MIRAGE_BIND_HYBRID_SPLATS 7  // uint per pixel: the nearest splat's depth key
// uint[MIRAGE_HYBRID_COUNTERS]: pairs given, projections, splats, pairs projecting, pairs facing
// away, candidates appended
#define MIRAGE_BIND_HYBRID_COUNTERS 8
#define MIRAGE_BIND_HYBRID_WINNERS 14           // uint per pixel: the winning point's index
#define MIRAGE_BIND_HYBRID_CANDIDATES 15        // uint[3 n]: (pixel, depth key, point index)
#define MIRAGE_BIND_HYBRID_POINT_ATTRIBUTES 16  // PointAttributes[], the same order
// uint[runs + 1]: the first work item of each run a workgroup projects, then the item count
#define MIRAGE_BIND_HYBRID_RUNS 17
// uint per work item: its taken points with a projection (the level of detail's probe)
#define MIRAGE_BIND_HYBRID_ITEM_SEEN 18
#define MIRAGE_HYBRID_COUNTERS 6
#define MIRAGE_HYBRID_COUNTER_CANDIDATES 5
#define MIRAGE_UNIT_HYBRID_DEPTH 4   // the frame's depth with the reflectors drawn
#define MIRAGE_UNIT_HYBRID_IDS 6     // usampler2D: the reflector triangle each pixel shows

#define MIRAGE_HYBRID_GROUP 8            // invocations per run of items (see hybrid_splat.comp)
#define MIRAGE_HYBRID_MAX_SPLAT 8        // the largest automatic splat side, in pixels
#define MIRAGE_HYBRID_EMPTY 0xFFFFFFFFu  // a pixel no splat reached (either word)
#define MIRAGE_HYBRID_WINNER_GROUP 64    // invocations per workgroup of hybrid_winner.comp

SHARED_BEGIN

// One point sample, in its object's space: its position (a vec4 in the positions buffer: xyz
// object space, w the instance, exact as a float below 2^24) and these. Two buffers rather than
// one of 48-byte points, so that each stays within llvmpipe's 128 MiB storage block at the
// 4,000,000 points --points allows (16 and 32 bytes a point; 48 would end at 2,796,202).
struct PointAttributes {
  vec4 normal;  // xyz: object-space unit normal; w: the point spacing (object space)
  vec4 albedo;  // rgb: linear albedo; w: 1 where the object is closed (its back faces hidden)
};

// The points a work item of `count` points takes at the level of detail's `stride` (every
// stride-th, in order): what the splatting shader projects, and what the host counts and groups
// into runs by.
SHARED_FN int hybrid_taken_points(int count, float stride) {
  return stride > 1.0f ? int(ceil(float(count) / stride)) : count;
}

// A point whose normal faces away from all three corners of a reflector triangle faces away
// from every point of it (each is a convex combination of the corners): on a closed surface it
// is hidden from that triangle, and the splatting skips it before the cubic.
SHARED_FN bool hybrid_faces_away(vec3 normal, vec3 q, vec3 v0, vec3 v1, vec3 v2) {
  return dot(normal, v0 - q) < 0.0f && dot(normal, v1 - q) < 0.0f && dot(normal, v2 - q) < 0.0f;
}

// The world-space spacing of a point sampled `spacing` apart in its object's space, under the
// model's linear part `linear` (any affine map: rotation, non-uniform scale, shear). Neighbours
// lie `spacing` apart along every direction of the surface's tangent plane (normal
// `object_normal`, object space), which `linear` stretches by between its two singular values
// there; the square splat must close the widest gap, so this is the larger, σ1 · spacing (a
// uniform scale s gives s · spacing; the mean, sqrt(σ1 σ2) · spacing, would leave holes along
// the stretched direction). σ1² is the larger eigenvalue of the 2 x 2 Gram matrix of the
// tangent basis's images. A zero normal falls back to the Frobenius norm, which bounds every
// stretch from above.
SHARED_FN float hybrid_world_spacing(mat3 linear, vec3 object_normal, float spacing) {
  float nn = dot(object_normal, object_normal);
  if (!(nn > 0.0f))
    return spacing *
           sqrt(dot(linear[0], linear[0]) + dot(linear[1], linear[1]) + dot(linear[2], linear[2]));
  vec3 n = object_normal / sqrt(nn);
  vec3 t1 = normalize(cross(n, abs(n.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
  vec3 a = linear * t1, b = linear * cross(n, t1);
  float aa = dot(a, a), bb = dot(b, b), ab = dot(a, b);
  float half_difference = 0.5f * (aa - bb);
  float largest = 0.5f * (aa + bb) + sqrt(half_difference * half_difference + ab * ab);
  return spacing * sqrt(largest);
}

// A splat's depth key: the push-back's float bits. Non-negative floats order as their bit
// patterns, so two distinct push-backs keep their order exactly, at any point count (the index
// of the nearest point is found apart: hybrid_winner.comp); MIRAGE_HYBRID_EMPTY (a NaN's bits)
// stays above every key.
SHARED_FN uint hybrid_depth_key(float push_back) {
  return floatBitsToUint(max(push_back, 0.0f));
}

// The front of a pixel: the splats whose push-back is within this fraction of the nearest's, the
// same surface, among which the one landed nearest the pixel's centre wins (a nearest-neighbour
// reconstruction in the image: sharper than whichever of the overlapping splats is nearest in
// depth, once splats are as large as their neighbours' gaps).
#define MIRAGE_HYBRID_FRONT_TOLERANCE 0.005f
// A winner word: the quantised squared distance of the splat's landing from the pixel's centre
// (output pixels², 1/32 steps, at most 1023) above the point's index (22 bits: 4,194,304 points).
#define MIRAGE_HYBRID_INDEX_BITS 22
#define MIRAGE_HYBRID_INDEX_MASK 0x3FFFFFu

// Whether push-back `depth_key` is in the front of a pixel whose nearest is `nearest` (both
// hybrid_depth_key; MIRAGE_HYBRID_EMPTY: no splat yet).
SHARED_FN bool hybrid_in_front(uint depth_key, uint nearest) {
  return nearest == MIRAGE_HYBRID_EMPTY ||
         uintBitsToFloat(depth_key) <=
             uintBitsToFloat(nearest) * (1.0f + MIRAGE_HYBRID_FRONT_TOLERANCE);
}

// Whether a splat that found `before` in its pixel's depth word (atomicMin's return) may be in
// the pixel's final front: within the tolerance of every splat before it there. The final
// nearest only lowers, so every splat of the final front appends itself as a candidate.
SHARED_FN bool hybrid_is_candidate(uint before, uint depth_key) {
  return hybrid_in_front(depth_key, before);
}

// The winner word of a candidate landed `distance2` output pixels² from the pixel's centre.
SHARED_FN uint hybrid_winner_word(float distance2, uint index) {
  uint d = uint(min(distance2 * 32.0f, 1023.0f));
  return (d << MIRAGE_HYBRID_INDEX_BITS) | (index & MIRAGE_HYBRID_INDEX_MASK);
}

SHARED_END

#endif  // MIRAGE_METHODS_HYBRID_HYBRID_SHARED_H
