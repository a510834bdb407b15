// Ray intersections with the simple proxies that stand in for the reflected scene, shared by the
// shaders and the C++ tests (which call this very code):
//  - a box (the room proxy of a parallax-corrected cube map, `envmap-box`; the ground billboard
//    and its transition walls in the billboard-to-environment morph);
//  - a parallelogram (a billboard quad);
//  - the morph of the impostor paper (§3.2): r_m = r_a + (r_1^d - r_a) h / H.
#ifndef MIRAGE_SHADING_PROXY_H
#define MIRAGE_SHADING_PROXY_H

#include "shading/glsl_compat.h"

// Box faces, as returned by ray_box_exit: axis * 2 + (max side ? 1 : 0).
#define MIRAGE_BOX_MIN_X 0
#define MIRAGE_BOX_MAX_X 1
#define MIRAGE_BOX_MIN_Y 2
#define MIRAGE_BOX_MAX_Y 3
#define MIRAGE_BOX_MIN_Z 4
#define MIRAGE_BOX_MAX_Z 5

SHARED_BEGIN

// 1 / x with the sign kept and zero replaced by a tiny value, so that slab tests on rays
// parallel to an axis give +-huge parameters instead of NaN (0 * inf).
SHARED_FN float safe_reciprocal(float x) {
  const float tiny = 1.0e-30f;
  return 1.0f / (abs(x) > tiny ? x : (x < 0.0f ? -tiny : tiny));
}

// Where the ray origin + t * dir leaves the box [bmin, bmax], t >= 0: the parameter t and the
// face it leaves through (MIRAGE_BOX_*). The ray may start inside the box (a reflector in a room)
// or enter it first. Returns -1 (face -1) if the ray misses the box or the box is behind it.
SHARED_FN float ray_box_exit(vec3 origin, vec3 dir, vec3 bmin, vec3 bmax, SHARED_OUT(int) face) {
  vec3 inv = vec3(safe_reciprocal(dir.x), safe_reciprocal(dir.y), safe_reciprocal(dir.z));
  vec3 t0 = (bmin - origin) * inv;
  vec3 t1 = (bmax - origin) * inv;
  vec3 t_near = min(t0, t1);
  vec3 t_far = max(t0, t1);
  float enter = max(max(t_near.x, t_near.y), t_near.z);
  float leave = t_far.x;
  int axis = 0;
  if (t_far.y < leave) {
    leave = t_far.y;
    axis = 1;
  }
  if (t_far.z < leave) {
    leave = t_far.z;
    axis = 2;
  }
  if (leave < max(enter, 0.0f)) {
    face = -1;
    return -1.0f;
  }
  face = axis * 2 + (dir[axis] > 0.0f ? 1 : 0);
  return leave;
}

// The parameter t > t_min at which the ray hits the parallelogram corner + u * edge_u +
// v * edge_v (u, v in [0, 1]) with edge_u perpendicular to edge_v, and its (u, v); -1 on a miss.
// Both sides of the quad count.
SHARED_FN float ray_quad(vec3 origin, vec3 dir, vec3 corner, vec3 edge_u, vec3 edge_v, float t_min,
                         SHARED_OUT(vec2) uv) {
  vec3 n = cross(edge_u, edge_v);
  float denom = dot(dir, n);
  if (abs(denom) < 1.0e-12f * dot(n, n)) return -1.0f;  // parallel to the plane
  float t = dot(corner - origin, n) / denom;
  if (!(t > t_min)) return -1.0f;
  vec3 local = origin + t * dir - corner;
  uv = vec2(dot(local, edge_u) / dot(edge_u, edge_u), dot(local, edge_v) / dot(edge_v, edge_v));
  if (uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f) return -1.0f;
  return t;
}

// Where the ray origin + t * dir (unit dir) leaves the sphere (centre, radius), t >= 0: the far
// root of |o + t d - c|^2 = r^2. Returns -1 if the ray misses the sphere or it lies behind.
SHARED_FN float ray_sphere_exit(vec3 origin, vec3 dir, vec3 centre, float radius) {
  vec3 oc = origin - centre;
  float b = dot(oc, dir);
  float c = dot(oc, oc) - radius * radius;
  float disc = b * b - c;
  if (disc < 0.0f) return -1.0f;
  float t = -b + sqrt(disc);
  return t >= 0.0f ? t : -1.0f;
}

// The direction a parallax-corrected cube map captured at `centre` is looked up with: towards
// the point where the ray leaves the proxy box, or the ray's own direction if it misses the box.
// `t` receives the distance along the unit `dir` to that point (MISS_DISTANCE-free: -1 on a miss).
SHARED_FN vec3 box_parallax_direction(vec3 origin, vec3 dir, vec3 bmin, vec3 bmax, vec3 centre,
                                      SHARED_OUT(float) t) {
  int face = -1;
  t = ray_box_exit(origin, dir, bmin, bmax, face);
  if (t < 0.0f) return dir;
  return origin + t * dir - centre;
}

// The same through a sphere proxy (Bjorke's, the special case the impostor paper starts from):
// towards the point where the ray leaves the sphere (sphere_centre, radius).
SHARED_FN vec3 sphere_parallax_direction(vec3 origin, vec3 dir, vec3 sphere_centre, float radius,
                                         vec3 centre, SHARED_OUT(float) t) {
  t = ray_sphere_exit(origin, dir, sphere_centre, radius);
  if (t < 0.0f) return dir;
  return origin + t * dir - centre;
}

// The billboard-to-environment morph (§3.2 of the impostor paper). A ray leaving a reflector hits
// a transition wall of height `wall_height` at `hit`, `height` above the ground billboard. It is
// replaced by r_m = r_a + (r_d - r_a) * height / wall_height, looked up in the environment map
// centred at `centre`: r_a points from the centre to the hit (height 0: exactly the ground's
// texel, continuous with the billboard), r_d is the ray's own direction (height H: plain
// environment mapping). Both are normalised before the blend, so that the blend weights
// directions and not the distance to the wall; the result is normalised too.
SHARED_FN vec3 morph_direction(vec3 hit, vec3 centre, vec3 dir, float height, float wall_height) {
  vec3 r_a = normalize(hit - centre);
  vec3 r_d = normalize(dir);
  float w = clamp(height / max(wall_height, 1.0e-20f), 0.0f, 1.0f);
  return normalize(r_a + (r_d - r_a) * w);
}

SHARED_END

#endif  // MIRAGE_SHADING_PROXY_H
