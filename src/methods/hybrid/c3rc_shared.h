// The continuous 3-ray camera (C3RC) of the hybrid backward-forward paper (§5), as the splatting
// shader and the C++ code (culling, tests) see it.
//
// A C3RC is built per reflector triangle v0 v1 v2: its construction rays are the reflected rays
// at the vertices, d0 d1 d2 (scaled by the vertices' distances to the eye: see reflectorC3rc).
// Its view volume is swept by the triangle T(λ) = (v0 + λ d0, v1 + λ d1, v2 + λ d2), λ ≥ 0;
// T(0) is the reflector triangle itself, the C3RC's image plane. A point Q projects where it
// lies in T(λ): the coplanarity of Q with T(λ) is a cubic in λ, and every root λ ≥ 0 at which
// Q's barycentrics in T(λ) are all in [0, 1] is a projection. The reflector point that sees Q is
// Σ w_k v_k (the barycentrics carried back to λ = 0), at distance |Q − Σ w_k v_k| from Q.
//
// The swept triangle's normal n(λ) = (T1 − T0) × (T2 − T0) = n0 + λ n1 + λ² n2 is quadratic; with
// it the cubic is n(λ) · (Q − v0 − λ d0) = 0. A construction ray k lies in T(λ)'s plane where
// d_k · n(λ) = 0 (the sidedness quadratics): only while the three rays are not on one side of
// T(λ) can the swept triangle fold over itself, which is when one C3RC projects a point more than
// once (a convergent-then-divergent C3RC: a concave reflector).
#ifndef MIRAGE_METHODS_HYBRID_C3RC_SHARED_H
#define MIRAGE_METHODS_HYBRID_C3RC_SHARED_H

#include "shading/glsl_compat.h"

// C3rcData.info.z flags
#define MIRAGE_C3RC_MULTIPLE 1     // the sidedness test allows a second projection
#define MIRAGE_C3RC_HULL 8         // bounding planes kept per C3RC
#define MIRAGE_C3RC_ROOT_STEPS 40  // the most steps of a bracketed root (c3rc_bracketed_root)

// A C3rcData.info.z flag: the placeholder of a degenerate triangle (never culled nor splatted).
#define MIRAGE_C3RC_DEGENERATE 2

SHARED_BEGIN

// One C3RC, in world space (the splatting shader) or in an object's space (the culling).
struct C3rcData {
  vec4 v0, v1, v2;  // xyz: the reflector triangle's vertices; w unused
  vec4 d0, d1, d2;  // xyz: construction rays (reflected rays at the vertices; any lengths)
  vec4 n0, n1, n2;  // xyz: coefficients of the swept triangle's normal n(λ) = n0 + λn1 + λ²n2
  vec4 info;        // x, y: the λ interval where the rays are not on one side (x > y: none);
                    // z: flags (MIRAGE_C3RC_*); w: the largest λ searched
  vec4 folds;       // [x, y] and [z, w]: two λ intervals (empty where the start is above the
                    // end) that hold every λ where T(λ) may fold (c3rc_cull.h), within info.xy
  vec4 hull[MIRAGE_C3RC_HULL];  // planes a·x ≤ h (xyz = a, unit; w = h) around the view volume
  ivec4 counts;                 // x: planes in hull; y: the reflector's instance + 1 (0: unset)
};

// The view volume lies in the hull: a point outside a plane (by more than rounding) has no
// projection. The cheap test before the cubic, and the culling's first test.
SHARED_FN bool c3rc_hull_contains(C3rcData c, vec3 q) {
  for (int i = 0; i < c.counts.x; ++i)
    if (dot(vec3(c.hull[i]), q) > c.hull[i].w + 1.0e-5f * (abs(c.hull[i].w) + 1.0f)) return false;
  return true;
}

// The coefficients of n(λ) for the triangle (v0, v1, v2) swept along (d0, d1, d2).
SHARED_FN void c3rc_normal_coefficients(vec3 v0, vec3 v1, vec3 v2, vec3 d0, vec3 d1, vec3 d2,
                                        SHARED_OUT(vec3) n0, SHARED_OUT(vec3) n1,
                                        SHARED_OUT(vec3) n2) {
  vec3 e1 = v1 - v0, e2 = v2 - v0, f1 = d1 - d0, f2 = d2 - d0;
  n0 = cross(e1, e2);
  n1 = cross(e1, f2) + cross(f1, e2);
  n2 = cross(f1, f2);
}

SHARED_FN vec3 c3rc_normal(C3rcData c, float lambda) {
  return vec3(c.n0) + lambda * (vec3(c.n1) + lambda * vec3(c.n2));
}

// The coplanarity cubic of Q: (c0, c1, c2, c3) with p(λ) = c0 + c1 λ + c2 λ² + c3 λ³.
SHARED_FN vec4 c3rc_cubic(C3rcData c, vec3 q) {
  vec3 q0 = q - vec3(c.v0), d = vec3(c.d0);
  vec3 n0 = vec3(c.n0), n1 = vec3(c.n1), n2 = vec3(c.n2);
  return vec4(dot(n0, q0), dot(n1, q0) - dot(n0, d), dot(n2, q0) - dot(n1, d), -dot(n2, d));
}

SHARED_FN float c3rc_poly(vec4 p, float x) {
  return p.x + x * (p.y + x * (p.z + x * p.w));
}

SHARED_FN float c3rc_poly_derivative(vec4 p, float x) {
  return p.y + x * (2.0f * p.z + x * 3.0f * p.w);
}

// The real roots of a x² + b x + c in ascending order (the numerically stable form); returns
// how many (0, 1 or 2). a = 0 degrades to the linear equation.
SHARED_FN int c3rc_quadratic_roots(float a, float b, float c, SHARED_OUT(float) r0,
                                   SHARED_OUT(float) r1) {
  r0 = 0.0f;
  r1 = 0.0f;
  float scale = max(max(abs(a), abs(b)), abs(c));
  if (scale == 0.0f) return 0;
  if (abs(a) <= 1.0e-12f * scale) {
    if (abs(b) <= 1.0e-12f * scale) return 0;
    r0 = -c / b;
    return 1;
  }
  float disc = b * b - 4.0f * a * c;
  if (disc < 0.0f) return 0;
  float s = sqrt(disc);
  float qq = -0.5f * (b + (b >= 0.0f ? s : -s));
  if (qq == 0.0f) {  // b = 0 and c = 0: a double root at 0
    return 1;
  }
  float x0 = qq / a, x1 = c / qq;
  r0 = min(x0, x1);
  r1 = max(x0, x1);
  return 2;
}

// The root of the monotonic p in [lo, hi] where p(lo), p(hi) differ in sign: Newton's method
// from lo (its first step is the linear estimate there), kept inside the bracket, bisection
// where Newton would leave it. It stops once |p(x)| is within float rounding of p's evaluation
// and the slope makes that a root to 1e-5 (far below a pixel), or the steps are a few ulps.
SHARED_FN float c3rc_bracketed_root(vec4 p, float lo, float hi) {
  float flo = c3rc_poly(p, lo);
  float dlo = c3rc_poly_derivative(p, lo);
  float x = dlo != 0.0f ? lo - flo / dlo : 0.5f * (lo + hi);
  if (!(x > lo && x < hi)) x = 0.5f * (lo + hi);
  for (int i = 0; i < MIRAGE_C3RC_ROOT_STEPS; ++i) {
    float f = c3rc_poly(p, x);
    float ax = abs(x);
    float rounding = 4.0e-7f * (abs(p.x) + ax * (abs(p.y) + ax * (abs(p.z) + ax * abs(p.w))));
    float df = c3rc_poly_derivative(p, x);
    // Within rounding of 0 where the cubic is steep enough that this pins x to 1e-5: done.
    // Where it is flat (near a double root) rounding says little: go on narrowing the bracket.
    if (f == 0.0f || (abs(f) <= rounding && abs(f) <= 1.0e-5f * max(1.0f, ax) * abs(df))) return x;
    if ((f < 0.0f) == (flo < 0.0f)) {
      lo = x;
      flo = f;
    } else {
      hi = x;
    }
    float next = df != 0.0f ? x - f / df : 0.5f * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5f * (lo + hi);
    // Float carries ~7 digits: stop at a few ulps of movement, or when the bracket is that tight.
    float tol = 4.0e-7f * max(1.0f, abs(x));
    if (abs(next - x) <= tol || hi - lo <= tol) return next;
    x = next;
  }
  return x;
}

// The critical points of the cubic p (roots of p') inside (0, lambda_max), ascending, as b1 <= b2
// (unused ones are lambda_max): with 0 and lambda_max they split the range into three
// monotonic pieces, each holding at most one root.
SHARED_FN void c3rc_breakpoints(vec4 p, float lambda_max, SHARED_OUT(float) b1,
                                SHARED_OUT(float) b2) {
  float k0 = 0.0f, k1 = 0.0f;
  int nk = c3rc_quadratic_roots(3.0f * p.w, 2.0f * p.z, p.y, k0, k1);
  b1 = lambda_max;
  b2 = lambda_max;
  if (nk >= 1 && k0 > 0.0f && k0 < lambda_max) b1 = k0;
  if (nk == 2 && k1 > 0.0f && k1 < lambda_max) {
    if (b1 == lambda_max)
      b1 = k1;
    else
      b2 = k1;
  }
}

// p at a breakpoint x, 0 where it is within rounding of 0 (|p| ≤ 1e-6 Σ|c_i| x^i) at a critical
// point: the cubic touches 0 there (a double root: Q on a caustic of the C3RC), which rounding
// would otherwise split into two roots ~sqrt(1e-7) away or lose altogether.
SHARED_FN float c3rc_poly_at_breakpoint(vec4 p, float x, float lambda_max) {
  float f = c3rc_poly(p, x);
  if (x <= 0.0f || x >= lambda_max) return f;  // not a critical point
  float size = abs(p.x) + x * (abs(p.y) + x * (abs(p.z) + x * abs(p.w)));
  return abs(f) <= 1.0e-6f * size ? 0.0f : f;
}

// The root of the cubic in piece `piece` (0..2) of [0, lambda_max] split at b1, b2, or -1.
// A root exactly at a breakpoint belongs to the piece it ends (and to piece 0 at λ = 0).
SHARED_FN float c3rc_piece_root(vec4 p, int piece, float b1, float b2, float lambda_max) {
  float lo = piece == 0 ? 0.0f : (piece == 1 ? b1 : b2);
  float hi = piece == 0 ? b1 : (piece == 1 ? b2 : lambda_max);
  if (hi <= lo) return -1.0f;
  float flo = c3rc_poly_at_breakpoint(p, lo, lambda_max);
  float fhi = c3rc_poly_at_breakpoint(p, hi, lambda_max);
  if (piece == 0 && flo == 0.0f) return 0.0f;
  if (fhi == 0.0f) return hi;
  if (flo == 0.0f || (flo < 0.0f) == (fhi < 0.0f)) return -1.0f;
  return c3rc_bracketed_root(p, lo, hi);
}

// Every root of the cubic p in [0, lambda_max], ascending, into roots.xyz; returns the count.
// Bracketing each monotonic piece is robust where the cubic degenerates to a quadratic or a
// line (nearly parallel construction rays, a flat reflector).
SHARED_FN int c3rc_cubic_roots(vec4 p, float lambda_max, SHARED_OUT(vec3) roots) {
  roots = vec3(0.0f);
  float b1 = 0.0f, b2 = 0.0f;
  c3rc_breakpoints(p, lambda_max, b1, b2);
  int count = 0;
  for (int piece = 0; piece < 3; ++piece) {
    float root = c3rc_piece_root(p, piece, b1, b2, lambda_max);
    if (root < 0.0f) continue;
    if (count == 0)
      roots.x = root;
    else if (count == 1)
      roots.y = root;
    else
      roots.z = root;
    ++count;
  }
  return count;
}

// Q's barycentrics (w0, w1, w2) in the swept triangle T(λ); w = -1 everywhere where T(λ) has
// collapsed (a focal line of the C3RC).
SHARED_FN vec3 c3rc_barycentrics(C3rcData c, float lambda, vec3 q) {
  vec3 p0 = vec3(c.v0) + lambda * vec3(c.d0);
  vec3 p1 = vec3(c.v1) + lambda * vec3(c.d1);
  vec3 p2 = vec3(c.v2) + lambda * vec3(c.d2);
  vec3 n = cross(p1 - p0, p2 - p0);
  float nn = dot(n, n);
  if (nn <= 0.0f) return vec3(-1.0f);
  float w0 = dot(cross(p1 - q, p2 - q), n) / nn;
  float w1 = dot(cross(p2 - q, p0 - q), n) / nn;
  return vec3(w0, w1, 1.0f - w0 - w1);
}

// The projections of Q: up to three (barycentrics w0, w1, w2; λ) with λ ≥ 0 and every
// barycentric ≥ −eps, in ascending λ. The roots are found piece by piece and the search stops
// at the first projection when `first_only` (the paper's one fragment per point) or when the
// sidedness test ruled out a second one (info.z without MIRAGE_C3RC_MULTIPLE). Returns the count.
SHARED_FN int c3rc_project(C3rcData c, vec3 q, float eps, bool first_only, SHARED_OUT(vec4) p0,
                           SHARED_OUT(vec4) p1, SHARED_OUT(vec4) p2) {
  p0 = vec4(0.0f);
  p1 = vec4(0.0f);
  p2 = vec4(0.0f);
  if (!c3rc_hull_contains(c, q)) return 0;
  bool single = first_only || (int(c.info.z) & MIRAGE_C3RC_MULTIPLE) == 0;
  vec4 p = c3rc_cubic(c, q);
  float b1 = 0.0f, b2 = 0.0f;
  c3rc_breakpoints(p, c.info.w, b1, b2);
  int count = 0;
  for (int piece = 0; piece < 3; ++piece) {
    float lambda = c3rc_piece_root(p, piece, b1, b2, c.info.w);
    if (!(lambda >= 0.0f)) continue;  // also NaN (a NaN λmax)
    vec3 w = c3rc_barycentrics(c, lambda, q);
    if (!(w.x >= -eps && w.y >= -eps && w.z >= -eps)) continue;  // also NaN
    vec4 proj = vec4(w, lambda);
    if (count == 0)
      p0 = proj;
    else if (count == 1)
      p1 = proj;
    else
      p2 = proj;
    ++count;
    if (single) break;
  }
  return count;
}

// The reflector point that sees a projection (barycentrics carried back to the base).
SHARED_FN vec3 c3rc_base_point(C3rcData c, vec4 proj) {
  return proj.x * vec3(c.v0) + proj.y * vec3(c.v1) + proj.z * vec3(c.v2);
}

// The area a small patch facing the rays at a projection keeps on its way to the screen (up to
// the perspective), relative to its own: T(λ)'s size against the base's, |n(λ)| / |n0| (within
// T(λ)'s plane the map to the base keeps barycentrics); T(λ)'s tilt against the ray through the
// point, |n̂(λ)·d̂| (a patch across the ray covers 1 / |n̂(λ)·d̂| of itself on T(λ)); and the
// base's foreshortening towards the eye, 1 / |n̂0·ê|. On a planar mirror the tilts cancel; near
// a caustic T(λ) turns along the rays and the patch spreads wide. `to_eye` is a unit vector.
SHARED_FN float c3rc_spread(C3rcData c, vec4 proj, vec3 to_eye) {
  vec3 nl = c3rc_normal(c, proj.w), n0 = vec3(c.n0);
  vec3 d = proj.x * vec3(c.d0) + proj.y * vec3(c.d1) + proj.z * vec3(c.d2);
  float grow = length(nl) / max(length(n0), 1.0e-30f);
  float tilt = abs(dot(nl, d)) / max(length(nl) * length(d), 1.0e-30f);
  float facing = abs(dot(n0, to_eye)) / max(length(n0), 1.0e-30f);
  return grow * tilt / max(facing, 1.0e-6f);
}

// The λ ≥ 0 values (up to 2, ascending) where construction ray k lies in T(λ)'s plane.
SHARED_FN int c3rc_side_crossings(C3rcData c, vec3 d, SHARED_OUT(float) r0, SHARED_OUT(float) r1) {
  float a = 0.0f, b = 0.0f;
  int n = c3rc_quadratic_roots(dot(d, vec3(c.n2)), dot(d, vec3(c.n1)), dot(d, vec3(c.n0)), a, b);
  r0 = 0.0f;
  r1 = 0.0f;
  int count = 0;
  if (n >= 1 && a >= 0.0f) {
    r0 = a;
    ++count;
  }
  if (n == 2 && b >= 0.0f) {
    if (count == 0)
      r0 = b;
    else
      r1 = b;
    ++count;
  }
  return count;
}

// The sides of the three construction rays relative to T(λ) agree (all on one side).
SHARED_FN bool c3rc_sides_agree(C3rcData c, float lambda) {
  vec3 n = c3rc_normal(c, lambda);
  float s0 = dot(vec3(c.d0), n), s1 = dot(vec3(c.d1), n), s2 = dot(vec3(c.d2), n);
  return (s0 >= 0.0f && s1 >= 0.0f && s2 >= 0.0f) || (s0 <= 0.0f && s1 <= 0.0f && s2 <= 0.0f);
}

SHARED_END

#ifndef MIRAGE_GLSL
static_assert(sizeof(mirage::shading::C3rcData) == (11 + MIRAGE_C3RC_HULL + 1) * 16,
              "C3rcData layout (std430)");
#endif

#endif  // MIRAGE_METHODS_HYBRID_C3RC_SHARED_H
