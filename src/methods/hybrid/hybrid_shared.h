// The hybrid method's data as the shaders and the C++ code see it: the point samples, the work
// items of the splatting pass, and the per-pixel splat key — a 32-bit word ordered by the
// push-back distance (the distance from the reflector to the point, the paper's visibility
// rule: the point nearest the reflector wins) with the point's index in its low bits, written
// with one atomicMin (GL 4.5 has no 64-bit atomics, and llvmpipe none either).
#ifndef MIRAGE_METHODS_HYBRID_HYBRID_SHARED_H
#define MIRAGE_METHODS_HYBRID_HYBRID_SHARED_H

#include "shading/glsl_compat.h"

// Storage bindings (the method's SSBO slot and after) and texture units.
#define MIRAGE_BIND_HYBRID_C3RCS 4   // C3rcData[]
#define MIRAGE_BIND_HYBRID_ITEMS 5   // ivec4 work items: C3RC, first point, count, unused
#define MIRAGE_BIND_HYBRID_POINTS 6  // PointData[] (every set, leaf order)
#define MIRAGE_BIND_HYBRID_SPLATS 7  // uint per pixel: the splat key
#define MIRAGE_BIND_HYBRID_COUNTERS \
  8  // uint[5]: pairs given, projections, splats, pairs projecting, pairs facing away
#define MIRAGE_UNIT_HYBRID_DEPTH 4   // the frame's depth with the reflectors drawn
#define MIRAGE_UNIT_HYBRID_PROBES 5  // samplerCubeArray: the background per reflector

#define MIRAGE_HYBRID_GROUP 8            // invocations per work item (see hybrid_splat.comp)
#define MIRAGE_HYBRID_MAX_SPLAT 8        // the largest automatic splat side, in pixels
#define MIRAGE_HYBRID_EMPTY 0xFFFFFFFFu  // a pixel no splat reached

SHARED_BEGIN

// One point sample, in its object's space.
struct PointData {
  vec4 position;  // xyz: object space; w: the instance (exact as a float below 2^24)
  vec4 normal;    // xyz: object-space unit normal; w: the point spacing (object space)
  vec4 albedo;    // rgb: linear albedo; w: 1 where the object is closed (its back faces hidden)
};

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

// The splat key of a point: its push-back quantised to the bits the index leaves free.
// `depth_scale` = (2^(32 - index_bits) - 1) / the largest push-back of the frame.
SHARED_FN uint hybrid_splat_key(float push_back, float depth_scale, int index_bits, uint index) {
  float levels = float((1u << uint(32 - index_bits)) - 1u);
  float q = clamp(floor(push_back * depth_scale), 0.0f, levels);
  return (uint(q) << uint(index_bits)) | index;
}

SHARED_FN uint hybrid_splat_index(uint key, int index_bits) {
  return key & ((1u << uint(index_bits)) - 1u);
}

// The bits the point indices need (at least 1, at most 22: ten bits of depth at worst).
SHARED_FN int hybrid_index_bits(uint point_count) {
  int bits = 1;
  while (bits < 22 && (1u << uint(bits)) < point_count) ++bits;
  return bits;
}

SHARED_END

#endif  // MIRAGE_METHODS_HYBRID_HYBRID_SHARED_H
