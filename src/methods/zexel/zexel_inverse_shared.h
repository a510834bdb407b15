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
// The includer defines, before including this file:
//   float zexel_cube_distance(int layer, vec3 direction);  // D along `direction` of cube
//       `layer`, interpolated as the GPU filters it (bilinear, seamless across faces)
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_INVERSE_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_INVERSE_SHARED_H

#include "shading/glsl_compat.h"
#include "shading/shading.h"

// Bisections of the bracket around a crossing before the final secant step: 2⁻⁵ of a step.
#define ZEXEL_INVERSE_BISECTIONS 5
#if ZEXEL_INVERSE_BISECTIONS < 1
#error "the search decides on a bracket after its last bisection: at least one"
#endif

SHARED_BEGIN

// A stored distance at least this large is the sky: a sky texel stores MISS_DISTANCE (1e30),
// and filtering towards one with any weight above 1e-10 lands above this too, far beyond any
// scene's distances.
SHARED_CONST float ZEXEL_SKY_DISTANCE = 1.0e-10f * MISS_DISTANCE;

// The in-front measure g(φ) of the header comment at u = (cos φ, sin φ); `distance` receives
// D. Angles are carried as such unit vectors: turning and halving them needs no sine or cosine.
SHARED_FN float zexel_inverse_gap(int layer, vec3 d, vec3 n, float h, vec2 u,
                                  SHARED_OUT(float) distance) {
  distance = zexel_cube_distance(layer, u.x * d + u.y * n);
  if (distance >= ZEXEL_SKY_DISTANCE) return h;  // the sky is in front of every point
  return distance * u.y - h;
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
// One loop reads the map once per iteration, marching or bisecting: llvmpipe runs both sides of
// every branch, so a bisection loop nested in the march would cost its reads at every step.
SHARED_FN float zexel_inverse_warp(int layer, vec3 q, vec3 dir, float step_angle, int max_steps,
                                   float max_slope, SHARED_OUT(vec3) hit_direction,
                                   SHARED_OUT(int) status, SHARED_OUT(int) samples) {
  vec3 d = normalize(dir);
  float qd = dot(q, d);
  float h = 0.0f;
  vec3 n = zexel_ray_plane(q, d, qd, h);
  float phi0 = atan(h, qd);
  int steps = clamp(int(ceil(phi0 / step_angle)), 1, max_steps);
  float dphi = phi0 / float(steps);
  vec2 turn = vec2(cos(dphi), sin(dphi));
  hit_direction = d;
  status = ZEXEL_INVERSE_SKY;
  samples = 0;
  int step = 0;                         // the next march sample
  vec2 march = normalize(vec2(qd, h));  // its angle: φ₀ − step dφ, exactly 0 (t = ∞) last
  int bisecting = 0;  // halvings left of the bracket [b, a] (a in front, b behind); 0: marching
  bool was_in_front = false;
  vec2 prev_u = march;
  float prev_g = 0.0f, prev_distance = 0.0f;
  vec2 a = march, b = march;
  float ga = 0.0f, da = 0.0f, gb = 0.0f, db = 0.0f;
  int iterations = (max_steps + 1) * (ZEXEL_INVERSE_BISECTIONS + 1);
  for (int k = 0; k < iterations && (step <= steps || bisecting > 0); ++k) {
    vec2 u = bisecting > 0 ? normalize(a + b) : (step == steps ? vec2(1.0f, 0.0f) : march);
    float distance = 0.0f;
    float g = zexel_inverse_gap(layer, d, n, h, u, distance);
    samples += 1;
    if (bisecting > 0) {
      if (g > 0.0f) {
        a = u;
        ga = g;
        da = distance;
      } else {
        b = u;
        gb = g;
        db = distance;
      }
      bisecting -= 1;
      // The chord |a − b| is the bracket's angle θ to a part θ²/24 (1e-6 at a 32nd of a step).
      bool continuous = da < ZEXEL_SKY_DISTANCE &&
                        abs(da - db) <= max_slope * min(da, db) * max(length(a - b), 1.0e-30f);
      if (bisecting == 0 && continuous) {
        status = ZEXEL_INVERSE_HIT;
        break;
      }
      // Rejected: the march goes on from the step behind the bracket (was_in_front is false).
    } else {
      bool in_front = g > 0.0f;
      if (was_in_front && !in_front) {
        a = prev_u;
        ga = prev_g;
        da = prev_distance;
        b = u;
        gb = g;
        db = distance;
        bisecting = ZEXEL_INVERSE_BISECTIONS;
      }
      was_in_front = in_front;
      prev_u = u;
      prev_g = g;
      prev_distance = distance;
      step += 1;
      // Turned by −dφ, renormalised: rounding then moves the samples a little along the ray,
      // never off it.
      march =
          normalize(vec2(march.x * turn.x + march.y * turn.y, march.y * turn.x - march.x * turn.y));
    }
  }
  if (status == ZEXEL_INVERSE_HIT)
    return zexel_secant_hit(d, n, h, qd, a, b, ga, gb, hit_direction);
  if (!was_in_front) status = ZEXEL_INVERSE_EXPOSED;
  return -1.0f;
}

SHARED_END

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_INVERSE_SHARED_H
