// The inverse warp of a depth-preserving cube map: the forward-mapped planar mirror paper's
// future work, a reference map serving a curved mirror. The map holds, per direction from its
// centre c, the distance D to what c saw there (the sky: MISS_DISTANCE). A reflected ray
// o + t d is searched along its image in the map (its epipolar line) for the first point where
// it passes behind the stored surface; shared by zexel_inverse.frag and the C++ tests.
//
// The search walks the angle φ between the ray's direction d and the direction from c to the
// ray's point. In the plane of c and the ray, with q = o − c, h = |q − (q·d) d| the distance from
// c to the ray's line and n the unit vector towards the ray from that line's nearest point:
//     direction(φ) = cos φ d + sin φ n,   |p(φ) − c| = h / sin φ,   t(φ) = h cot φ − q·d,
// φ from φ₀ = angle(q, d) at t = 0 down to 0 at t = ∞. Equal steps in φ are equal steps across
// the map, so a step of about one texel's angle visits every texel of the epipolar line once,
// and the whole line is at most π long. The ray is in front of the stored surface where
//     g(φ) = D(direction(φ)) sin φ − h > 0,
// a form that stays finite at t = ∞ (g = −h: behind anything but the sky).
//
// Where the ray stays well in front of the stored surface the search crosses a stretch of steps
// in one read of a coarser level of lower bounds (zexel_bounds_shared.h): coarse to fine, one
// level coarser after a stretch crossed, one finer after a stretch refused, down to the single
// steps, so that it meets the same samples near a crossing as a search without them.
//
// The includer defines, before including this file:
//   float zexel_cube_distance(int layer, vec3 direction, int level);  // level 0: D along
//       `direction` of cube `layer`, interpolated as the GPU filters it (bilinear, seamless
//       across faces); a level ≥ ZEXEL_BOUND_FIRST_LEVEL: the lower bound B_L, likewise
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_INVERSE_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_INVERSE_SHARED_H

#include "methods/zexel/zexel_bounds_shared.h"
#include "shading/glsl_compat.h"
#include "shading/shading.h"

// Bisections of the bracket around a crossing before the final secant step: 2⁻⁵ of a step.
#define ZEXEL_INVERSE_BISECTIONS 5
#if ZEXEL_INVERSE_BISECTIONS < 1
#error "the search decides on a bracket after its last bisection: at least one"
#endif

SHARED_BEGIN

// The in-front measure g(φ) of the header comment at u = (cos φ, sin φ), D = `distance` read
// there. Angles are carried as such unit vectors: turning and halving them needs no sine or
// cosine.
SHARED_FN float zexel_inverse_gap(float distance, float h, vec2 u) {
  if (distance >= ZEXEL_SKY_DISTANCE) return h;  // the sky is in front of every point
  return distance * u.y - h;
}

// u turned by −v (towards t = ∞).
SHARED_FN vec2 zexel_turn_back(vec2 u, vec2 v) {
  return vec2(u.x * v.x + u.y * v.y, u.y * v.x - u.x * v.y);
}

// The turn twice as far as v.
SHARED_FN vec2 zexel_doubled(vec2 v) {
  return vec2(v.x * v.x - v.y * v.y, 2.0f * v.x * v.y);
}

// What a search found.
#define ZEXEL_INVERSE_SKY 0      // nothing: the ray leaves the scene
#define ZEXEL_INVERSE_HIT 1      // the stored surface
#define ZEXEL_INVERSE_EXPOSED 2  // no hit, but the ray ends behind a surface (see below)

// The plane holding the ray (through q along unit d, qd = q.d) and the centre: returns its unit
// direction n, perpendicular to d, from the centre towards the ray's nearest point, and sets h,
// the ray's distance from the centre. A ray through the centre has no plane of its own: any
// perpendicular will do, with an offset far below any texel.
SHARED_FN vec3 zexel_ray_plane(vec3 q, vec3 d, float qd, SHARED_OUT(float) h) {
  vec3 towards = q - qd * d;
  h = length(towards);
  float least = 1.0e-6f * max(length(q), 1.0e-6f);
  vec3 n = abs(d.x) < 0.9f ? normalize(cross(d, vec3(1.0f, 0.0f, 0.0f)))
                           : normalize(cross(d, vec3(0.0f, 1.0f, 0.0f)));
  if (h > least) n = towards / h;
  h = max(h, least);
  return n;
}

// The hit within the bracket [b, a] (angles in the ray's plane, a in front with gap ga > 0, b
// behind with gb <= 0): the secant step on the chord, from b's side, since b may be (1, 0)
// (t = ∞), where the crossing can lie a tiny angle away. Returns t; sets the hit's direction.
SHARED_FN float zexel_secant_hit(vec3 d, vec3 n, float h, float qd, vec2 a, vec2 b, float ga,
                                 float gb, SHARED_OUT(vec3) hit_direction) {
  vec2 u = normalize(b + (a - b) * (-gb / (ga - gb)));
  hit_direction = u.x * d + u.y * n;
  return max(h * u.x / u.y - qd, 0.0f);
}

// Where the march stands between reads: its steps along the line (the next one `step`, at the
// angle `march`), and the bounds' level read next with its stretch.
struct ZexelMarch {
  int steps;        // the line's steps: the last one at φ = 0 (t = ∞)
  int step;         // the next step read
  vec2 march;       // its angle: φ₀ − step dφ
  vec2 turn;        // one step's angle, dφ
  int level;        // the bounds' level read next; 0: the single steps
  int span;         // that level's stretch, in steps
  vec2 half_turn;   // half the stretch's angle
  int bounds_from;  // the first step after which the bounds are tried again
  int first;        // the finest level whose stretch holds two steps or more
  int first_span;   // its stretch (each coarser level's twice the finer one's)
  vec2 first_half;  // half its angle
  int top_level;    // the coarsest level read (first > top_level: no bounds)
};

// The last step read and the bracket [b, a] of a crossing being refined (a in front, b behind).
struct ZexelBracket {
  int bisecting;  // halvings left; 0: marching
  bool was_in_front;
  vec2 prev_u;
  float prev_g, prev_distance;
  vec2 a, b;
  float ga, da, gb, db;
};

SHARED_FN ZexelMarch zexel_march_start(float phi0, float qd, float h, float step_angle,
                                       int max_steps, float texel_angle, int top_level) {
  ZexelMarch m;
  m.steps = clamp(int(ceil(phi0 / step_angle)), 1, max_steps);
  float dphi = phi0 / float(m.steps);
  m.turn = vec2(cos(dphi), sin(dphi));
  m.step = 0;
  m.march = normalize(vec2(qd, h));
  m.top_level = top_level;
  m.first = ZEXEL_BOUND_FIRST_LEVEL;
  while (m.first <= top_level && zexel_bound_span(m.first, texel_angle, dphi) < 2) m.first += 1;
  m.first_span = m.first <= top_level ? zexel_bound_span(m.first, texel_angle, dphi) : 0;
  float half_angle = 0.5f * float(m.first_span) * dphi;
  m.first_half = vec2(cos(half_angle), sin(half_angle));
  m.level = 0;
  m.span = 0;
  m.half_turn = m.first_half;
  m.bounds_from = 0;
  return m;
}

SHARED_FN ZexelBracket zexel_bracket_start(vec2 u) {
  ZexelBracket k;
  k.bisecting = 0;
  k.was_in_front = false;
  k.prev_u = u;
  k.a = u;
  k.b = u;
  k.prev_g = 0.0f;
  k.prev_distance = 0.0f;
  k.ga = 0.0f;
  k.da = 0.0f;
  k.gb = 0.0f;
  k.db = 0.0f;
  return k;
}

// One halving of the bracket at u (gap g, distance read): true once the last halving leaves a
// bracket across a surface, false while halving and when the crossing is rejected as a
// discontinuity (the march then goes on from the step behind it: was_in_front is false).
SHARED_FN bool zexel_bisect(SHARED_INOUT(ZexelBracket) k, vec2 u, float g, float distance,
                            float max_slope) {
  if (g > 0.0f) {
    k.a = u;
    k.ga = g;
    k.da = distance;
  } else {
    k.b = u;
    k.gb = g;
    k.db = distance;
  }
  k.bisecting -= 1;
  // The chord |a − b| is the bracket's angle θ to a part θ²/24 (1e-6 at a 32nd of a step).
  bool continuous =
      k.da < ZEXEL_SKY_DISTANCE &&
      abs(k.da - k.db) <= max_slope * min(k.da, k.db) * max(length(k.a - k.b), 1.0e-30f);
  return k.bisecting == 0 && continuous;
}

// A read `bound` of the bounds over the stretch from the march's angle: crosses it (true, the
// march at its end, one level coarser next) where the ray stays in front all along — the bound
// times the smaller sine of its ends still exceeds h, sin being concave on [0, π] — else tries
// one level finer, or the single steps for a stretch's length. A stretch that would pass t = ∞
// ends there, within the cone the bound covers.
SHARED_FN bool zexel_cross_stretch(SHARED_INOUT(ZexelMarch) m, float bound, float h) {
  bool last = m.step + m.span >= m.steps;
  vec2 end = last ? vec2(1.0f, 0.0f) : zexel_turn_back(m.march, zexel_doubled(m.half_turn));
  if (bound >= ZEXEL_SKY_DISTANCE || bound * min(m.march.y, end.y) > h) {
    m.step = min(m.step + m.span, m.steps);  // its steps all in front: the single step there
    m.march = normalize(end);                // finds it so again
    if (m.level < m.top_level && !last) {
      m.level += 1;
      m.span *= 2;
      m.half_turn = normalize(zexel_doubled(m.half_turn));
    }
    if (last) m.level = 0;
    return true;
  }
  m.level -= 1;
  m.span /= 2;
  m.half_turn = normalize(vec2(1.0f + m.half_turn.x, m.half_turn.y));
  if (m.level < m.first) {
    m.level = 0;
    m.bounds_from = m.step + m.first_span;
  }
  return false;
}

// The single step at u (gap g, distance read): a crossing from in front to behind opens a
// bracket; a step in front lets the bounds be tried next. Returns whether the march moved on
// without a bracket to refine.
SHARED_FN bool zexel_single_step(SHARED_INOUT(ZexelMarch) m, SHARED_INOUT(ZexelBracket) k, vec2 u,
                                 float g, float distance) {
  bool in_front = g > 0.0f;
  if (k.was_in_front && !in_front) {
    k.a = k.prev_u;
    k.ga = k.prev_g;
    k.da = k.prev_distance;
    k.b = u;
    k.gb = g;
    k.db = distance;
    k.bisecting = ZEXEL_INVERSE_BISECTIONS;
  }
  k.was_in_front = in_front;
  k.prev_u = u;
  k.prev_g = g;
  k.prev_distance = distance;
  m.step += 1;
  // Turned by −dφ, renormalised: rounding then moves the samples a little along the ray, never
  // off it.
  m.march = normalize(zexel_turn_back(m.march, m.turn));
  if (in_front && m.first <= m.top_level && m.step >= m.bounds_from && m.step < m.steps) {
    m.level = m.first;
    m.span = m.first_span;
    m.half_turn = m.first_half;
  }
  return k.bisecting == 0;
}

// The ray origin + t dir's first hit on the surface the map stores, as t; `q` is the ray's
// origin relative to the map's centre. Steps of `step_angle` radians (at most `max_steps`) find
// the first step from in front to behind; ZEXEL_INVERSE_BISECTIONS halvings and a secant step
// refine it. A crossing where the stored distance changes faster than `max_slope` · D per
// radian is no surface but the interpolation across a depth discontinuity (the ray passed behind
// a silhouette): it is rejected and the march goes on. A ray that ends behind a surface without
// a hit (t = -1, status ZEXEL_INVERSE_EXPOSED) went where the map did not see: it struck
// something hidden from the centre, or passed beside the occluder to the sky; the map cannot
// tell. `hit_direction` receives the unit direction from the centre to the hit (where the map's
// colour is read), `status` what was found (ZEXEL_INVERSE_*), `samples` the map reads.
//
// A ray that leaves the sphere of radius `far` (the farthest distance the map holds) can hit
// nothing more: the march goes to its last step at once.
//
// With bounds up to `top_level` (zexel_bound_top_level of the face size whose texel spans
// `texel_angle`; 0: none), a step found in front is followed by the bounds' reads: a stretch
// crossed moves the march to its end (one level coarser next), a stretch refused tries one level
// finer, and below the first level the single steps resume, for a stretch's length before the
// bounds are tried again. The march lands only on its own steps, each skipped one in front, so
// that the crossing and its refinement are the same as with `top_level` 0 (no bounds).
//
// One loop reads the map once per iteration, marching, skipping or bisecting: llvmpipe runs both
// sides of every branch, so a bisection loop nested in the march would cost its reads at every
// step.
SHARED_FN float zexel_inverse_warp(int layer, vec3 q, vec3 dir, float step_angle, int max_steps,
                                   float max_slope, float texel_angle, int top_level, float far,
                                   SHARED_OUT(vec3) hit_direction, SHARED_OUT(int) status,
                                   SHARED_OUT(int) samples) {
  vec3 d = normalize(dir);
  float qd = dot(q, d);
  float h = 0.0f;
  vec3 n = zexel_ray_plane(q, d, qd, h);
  ZexelMarch m =
      zexel_march_start(atan(h, qd), qd, h, step_angle, max_steps, texel_angle, top_level);
  ZexelBracket k = zexel_bracket_start(m.march);
  hit_direction = d;
  status = ZEXEL_INVERSE_SKY;
  samples = 0;
  int iterations = (max_steps + 1) * (ZEXEL_INVERSE_BISECTIONS + 2);
  for (int i = 0; i < iterations && (m.step <= m.steps || k.bisecting > 0); ++i) {
    bool bounding = k.bisecting == 0 && m.level > 0;
    vec2 u = k.bisecting > 0 ? normalize(k.a + k.b)
                             : (bounding ? zexel_turn_back(m.march, m.half_turn)
                                         : (m.step == m.steps ? vec2(1.0f, 0.0f) : m.march));
    // One read an iteration, of the distance or of a bound (llvmpipe runs both sides of a
    // branch).
    float distance = zexel_cube_distance(layer, u.x * d + u.y * n, bounding ? m.level : 0);
    float g = zexel_inverse_gap(distance, h, u);
    samples += 1;
    // Where the march has now been decided up to, when it moved on.
    vec2 reached = u;
    bool moved = false;
    if (k.bisecting > 0) {
      if (zexel_bisect(k, u, g, distance, max_slope)) {
        status = ZEXEL_INVERSE_HIT;
        break;
      }
    } else if (bounding) {
      moved = zexel_cross_stretch(m, distance, h);
      reached = m.march;
    } else {
      moved = zexel_single_step(m, k, u, g, distance);
    }
    // Past the farthest distance the map holds (and moving away from the centre: φ ≤ π/2) the
    // ray is in front of the sky alone: no hit is left, and the last step (t = ∞) decides
    // between the sky and an exposure, as it would at the end of the march.
    if (moved && m.step < m.steps && reached.x >= 0.0f && h > far * reached.y) {
      m.step = m.steps;
      m.level = 0;
      k.was_in_front = false;
    }
  }
  if (status == ZEXEL_INVERSE_HIT)
    return zexel_secant_hit(d, n, h, qd, k.a, k.b, k.ga, k.gb, hit_direction);
  if (!k.was_in_front) status = ZEXEL_INVERSE_EXPOSED;
  return -1.0f;
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_INVERSE_SHARED_H
