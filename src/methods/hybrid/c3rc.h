// Building continuous 3-ray cameras on the CPU (the shared math is c3rc_shared.h): one per
// reflector triangle from the eye and the vertex normals, moved into an object's space for the
// culling, with the largest λ worth searching and the fold intervals filled in.
#pragma once

#include "core/math.h"
#include "methods/hybrid/c3rc_shared.h"

namespace mirage {

using shading::C3rcData;

// The C3RC of the triangle (v0, v1, v2) swept along the rays (d0, d1, d2) (any lengths), with
// roots searched up to lambda_max. Fills the normal coefficients, the hull planes and the λ
// ranges where the rays are not on one side of the swept triangle, where it may fold (their
// hull info.xy, the two intervals folds, MIRAGE_C3RC_MULTIPLE).
C3rcData makeC3rc(const vec3& v0, const vec3& v1, const vec3& v2, const vec3& d0, const vec3& d1,
                  const vec3& d2, float lambda_max);

// The reflected-ray C3RC of a reflector triangle seen from `eye`: construction rays are the
// reflected rays at the vertices, with each vertex normal turned to the eye's side the way the
// reflector shader turns it (facing_normal with the triangle's geometric normal). With
// `eye_scaled` each ray's length is its vertex's distance to the eye — then on a plane the rays
// leave the mirrored eye in step and the C3RC is exactly its pinhole camera — else unit length
// (the paper's). lambda_max is set so that every point within `reach` of the triangle is
// searched.
C3rcData reflectorC3rc(const vec3& eye, const vec3 v[3], const vec3 n[3], float reach,
                       bool eye_scaled = true);

// The same C3RC in the space that `m` (an affine map) takes world points to: vertices and ray
// directions transformed, λ unchanged (projection is affine-invariant), so a kd-tree built in
// an object's space answers a query moved by the inverse of the object's transform.
C3rcData transformC3rc(const C3rcData& c, const mat4& m);

// The distance from the origin to the triangle (a, b, c): the shortest Σ w_k d_k over the
// barycentric simplex, which bounds λ = |Q − v(w)| / |d(w)|.
float distanceToTriangle(const vec3& a, const vec3& b, const vec3& c);

}  // namespace mirage
