// Depth-map impostors as the shaders and the C++ code see them (the impostor paper, §4.3): the
// storage layout, the ray's clipping to the depth-map camera's frustum and its projection into
// texel space (steps 2-3), the way back from a fraction of the projected ray to the distance
// along the 3-D ray, and the brute-force walk along the projected ray over the full depth map
// (the baseline §4.1 argues against). The SRDM search itself is srdm_intersect_shared.h.
#ifndef MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_SHARED_H
#define MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_SHARED_H

#include "shading/glsl_compat.h"

// Storage binding and texture units of the depthmap method (after the billboards' 4, 6, 7).
#define MIRAGE_BIND_DEPTHMAPS 4        // SSBO DepthMapData[] (MIRAGE_BIND_METHOD_SSBO)
#define MIRAGE_UNIT_DEPTHMAP_COLOR 8   // sampler2DArray RGBA16F, mip-mapped; layer = map
#define MIRAGE_UNIT_DEPTHMAP_SRDM 9    // sampler2DArray RGBA32F; x pair, y row, layer map n + i
#define MIRAGE_UNIT_DEPTHMAP_DEPTH 10  // sampler2DArray (depth); layer = map
// SSBO int[]: the objects' candidate lists per reflector and direction cell: (first, count) of
// list L at 2 L and 2 L + 1, pointing at the first maps of its objects further on.
#define MIRAGE_BIND_DEPTHMAP_LISTS 9

// The ray-depth-map search the depth-map shader compiles in (its define DEPTHMAP_SEARCH):
#define MIRAGE_DEPTHMAP_SEARCH_SRDM 0             // one SRDM row (the paper)
#define MIRAGE_DEPTHMAP_SEARCH_LINEAR 1           // --depthmap-search linear: the full-map walk
#define MIRAGE_DEPTHMAP_SEARCH_HIT 2              // --srdm-rows 2 --srdm-second hit
#define MIRAGE_DEPTHMAP_SEARCH_INTERPOLATE 3      // --srdm-rows 2 --srdm-second interpolate
#define MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE 4  // --srdm-rows 2 --srdm-second hit-interpolate

SHARED_BEGIN

// One depth map of one object. The maps of an object are consecutive; the first holds their
// count, so that a shader walks objects by skipping info.w maps at a time.
struct DepthMapData {
  mat4 view_proj;  // world -> clip of the map's camera, moved with its object
  vec4 forward;    // xyz: the camera's viewing direction (world); w: 2 tan(fov / 2) / w, the
                   // world size of a texel per unit of eye depth
  ivec4 info;      // x: layer (colour, depth); y: first SRDM layer (domain 0); z: instance;
                   // w: on an object's first map, its map count (else 0)
  vec4 bound;      // xyz: the centre of the sphere the map frames (world); w: its radius: all
                   // the map holds lies inside it
};

// Whether the ray origin + t dir meets the sphere (centre, radius) at some t in [t0, t1]: a ray
// that does not cannot hit anything a map framing the sphere holds, and skips its search.
SHARED_FN bool depthmap_sphere_overlaps(vec3 origin, vec3 dir, vec4 sphere, float t0, float t1) {
  vec3 oc = origin - vec3(sphere.x, sphere.y, sphere.z);
  float a = dot(dir, dir);
  float b = dot(oc, dir);
  float c = dot(oc, oc) - sphere.w * sphere.w;
  float disc = b * b - a * c;
  if (disc < 0.0f || a <= 0.0f) return false;
  float root = sqrt(disc);
  return (-b + root) / a >= t0 && (-b - root) / a <= t1;
}

// Clips the ray origin + t dir, t in [t0, t1], to the clip volume -w <= x, y, z <= w of
// view_proj (Liang-Barsky on homogeneous coordinates: every plane is linear in t). Returns false
// when nothing is left; else narrows [t0, t1].
SHARED_FN bool depthmap_clip(mat4 view_proj, vec3 origin, vec3 dir, SHARED_INOUT(float) t0,
                             SHARED_INOUT(float) t1) {
  vec4 a = view_proj * vec4(origin, 1.0f);
  vec4 b = view_proj * vec4(dir, 0.0f);
  for (int plane = 0; plane < 6; ++plane) {
    int axis = plane / 2;
    float sign = (plane % 2) == 0 ? 1.0f : -1.0f;
    // f(t) = w + sign * coordinate >= 0 inside.
    float fa = a.w + sign * (axis == 0 ? a.x : (axis == 1 ? a.y : a.z));
    float fb = b.w + sign * (axis == 0 ? b.x : (axis == 1 ? b.y : b.z));
    if (abs(fb) < 1.0e-20f) {
      if (fa < 0.0f) return false;
      continue;
    }
    float t = -fa / fb;
    if (fb > 0.0f)
      t0 = max(t0, t);
    else
      t1 = min(t1, t);
  }
  return t0 < t1;
}

// The texel-space point (x, y in texels, d the window depth in [0, 1]) of a clip-space point.
SHARED_FN vec3 depthmap_texel_point(vec4 clip, float w) {
  vec3 ndc = vec3(clip.x, clip.y, clip.z) / clip.w;
  return vec3((ndc.x * 0.5f + 0.5f) * w, (ndc.y * 0.5f + 0.5f) * w, ndc.z * 0.5f + 0.5f);
}

// The fraction mu of the way along the 3-D segment whose projection is the fraction lambda of
// the way along the projected one, the segment's ends having clip w0 and w1 (perspective: the
// projected point at mu is ((1 - mu) P0 + mu P1) / ((1 - mu) w0 + mu w1)).
SHARED_FN float depthmap_unproject_fraction(float lambda, float w0, float w1) {
  return lambda * w0 / max((1.0f - lambda) * w1 + lambda * w0, 1.0e-30f);
}

SHARED_END

#ifndef MIRAGE_GLSL
static_assert(sizeof(mirage::shading::DepthMapData) == 7 * 16, "DepthMapData layout");
#endif

#endif  // MIRAGE_METHODS_DEPTHMAP_DEPTHMAP_SHARED_H
