// Method `depthmap`: the impostor paper's depth-map impostors (§4.3) inside its order-K pixel
// algorithm (methods/impostor/impostor_trace.glsl). Per bounce, each depth-mapped object is
// tested through its maps in order of how nearly each looks along the ray, until one is hit
// (depthmap_maps_shared.h): the ray is clipped to that camera's frustum, projected into texel space, and searched in one SRDM row (or two, or the
// full map with --depthmap-search linear); a hit nearer than every billboard ends the path with
// the map's colour at the hit, filtered over the ray differential's footprint. A reflector's
// maps of itself (--self-maps) are searched by the rays that leave it: a hit there reflects the
// ray about the map's normal (self-reflection), as a reflective billboard does.
#include "render/shaders/reflector.glsl"
#include "methods/impostor/impostor_counts.glsl"
#include "methods/depthmap/depthmap_shared.h"

layout(std430, binding = MIRAGE_BIND_DEPTHMAPS) readonly buffer DepthMapBlock {
  DepthMapData depthmaps[];
};
layout(std430, binding = MIRAGE_BIND_DEPTHMAP_LISTS) readonly buffer DepthMapListBlock {
  int depthmap_lists[];
};
layout(binding = MIRAGE_UNIT_DEPTHMAP_COLOR) uniform sampler2DArray u_depthmap_color;
layout(binding = MIRAGE_UNIT_DEPTHMAP_SRDM) uniform sampler2DArray u_srdm;
layout(binding = MIRAGE_UNIT_DEPTHMAP_DEPTH) uniform sampler2DArray u_depthmap_depth;
uniform int u_depthmap_size = 256;
uniform int u_srdm_n = 60;
uniform int u_srdm_m = 8;
// DEPTHMAP_SEARCH (a MIRAGE_DEPTHMAP_SEARCH_* value) and DEPTHMAP_TRIES (--depthmap-tries: how
// many of an object's maps a ray tries until one is hit) are defined by the method: the shader
// compiles in the one search it uses, since llvmpipe would pay for the others (it runs both
// sides of a branch), and a constant bound lets the map loop fold at one try.
#ifndef DEPTHMAP_SEARCH
#define DEPTHMAP_SEARCH MIRAGE_DEPTHMAP_SEARCH_SRDM
#endif
#ifndef DEPTHMAP_TRIES
#define DEPTHMAP_TRIES 2
#endif

// The SRDM layer of domain 0 of the map being searched.
int g_srdm_base = 0;
vec4 srdm_point_pair(int domain, int row, int pair) {
  return texelFetch(u_srdm, ivec3(pair, row, g_srdm_base + domain), 0);
}
#include "methods/depthmap/srdm_intersect_shared.h"

float depthmap_depth(int layer, int x, int y) {
  return texelFetch(u_depthmap_depth, ivec3(x, y, layer), 0).r;
}
#include "methods/depthmap/depthmap_march_shared.h"

// DEPTHMAP_SELF (defined by the method when there are self maps) compiles the self-reflection
// paths in; without it they fold away, so that scenes without self maps pay nothing for them
// (llvmpipe runs both sides of a branch).
#ifdef DEPTHMAP_SELF
const bool kSelfMaps = true;
#else
const bool kSelfMaps = false;
#endif

// A map's normal at texel-space (u, v) of its layer, in world space (self maps only).
vec3 depthmap_normal(vec3 uv_layer, int instance) {
  vec4 texel = textureLod(u_depthmap_color, uv_layer, 0.0f);
  return normalize(mat3(instances[instance].normal_matrix) * (texel.rgb / max(texel.a, 1.0e-4f)));
}

// Searches one map for the ray's first hit with t_min < t < t_best (see impostor_extra_hit).
bool depthmap_search(DepthMapData map, bool self, vec3 origin, vec3 dir,
                     float t_min, inout float t_best, vec3 dox, vec3 doy, vec3 ddx, vec3 ddy,
                     inout vec4 end) {
  float w = float(u_depthmap_size);
  float t0 = t_min, t1 = t_best;
  // A ray leaving the surface the map holds starts on it: skip two texels' width of it, so
  // that the simplified surface around the origin is not taken for a hit.
  if (self) t0 = max(t0, 2.0f * map.forward.w * max((map.view_proj * vec4(origin, 1.0f)).w, 0.0f));
  if (!depthmap_clip(map.view_proj, origin, dir, t0, t1)) return false;
  vec4 c0 = map.view_proj * vec4(origin + t0 * dir, 1.0f);
  vec4 c1 = map.view_proj * vec4(origin + t1 * dir, 1.0f);
  vec3 p0 = depthmap_texel_point(c0, w), p1 = depthmap_texel_point(c1, w);
  g_srdm_base = map.info.y;
#if DEPTHMAP_SEARCH == MIRAGE_DEPTHMAP_SEARCH_LINEAR
  int examined;
  float lambda = depthmap_march(map.info.x, u_depthmap_size, p0, p1, examined);
#else
  const bool hit_first = DEPTHMAP_SEARCH == MIRAGE_DEPTHMAP_SEARCH_HIT ||
                         DEPTHMAP_SEARCH == MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE;
  const bool interpolate = DEPTHMAP_SEARCH == MIRAGE_DEPTHMAP_SEARCH_INTERPOLATE ||
                           DEPTHMAP_SEARCH == MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE;
  float lambda = srdm_search(p0, p1, u_srdm_n, u_depthmap_size, u_srdm_m, hit_first, interpolate);
#endif
  if (lambda < 0.0f) return false;
  float mu = depthmap_unproject_fraction(lambda, c0.w, c1.w);
  float t = t0 + mu * (t1 - t0);
  if (t >= t_best) return false;
  vec3 hit = p0 + (p1 - p0) * lambda;
  // A surface is hit from its front: a self hit facing away is the ray's own start (or a
  // silhouette's error), not a reflection.
  if (self && dot(depthmap_normal(vec3(hit.xy / w, float(map.info.x)), map.info.z), dir) >= 0.0f)
    return false;
  t_best = t;
  // The footprint: the ray differential at the hit against a texel's world size there (clip w
  // is the eye depth along the camera's axis).
  float eye_depth = mix(c0.w, c1.w, mu);
  float texel = map.forward.w * max(eye_depth, 1.0e-6f);
  float spread = max(length(dox + t * ddx), length(doy + t * ddy));
  end = vec4(hit.x / w, hit.y / w, float(map.info.x), log2(max(spread / texel, 1.0e-8f)));
  return true;
}

// The ray that depthmap_try searches (set by impostor_extra_hit), the nearest hit so far and
// what it found.
vec3 g_origin, g_dir, g_dox, g_doy, g_ddx, g_ddy;
float g_t_min, g_t_best;
vec4 g_end;
vec3 depthmap_axis(int map) { return depthmaps[map].forward.xyz; }
bool depthmap_try(int map) {
  return depthmap_search(depthmaps[map], false, g_origin, g_dir, g_t_min, g_t_best, g_dox, g_doy,
                         g_ddx, g_ddy, g_end);
}
#include "methods/depthmap/depthmap_maps_shared.h"

bool impostor_extra_hit(vec3 origin, vec3 dir, int from, bool reflective, float t_min,
                        inout float t_best, vec3 dox, vec3 doy, vec3 ddx, vec3 ddy, out vec4 end) {
  g_origin = origin;
  g_dir = dir;
  g_dox = dox;
  g_doy = doy;
  g_ddx = ddx;
  g_ddy = ddy;
  g_t_min = t_min;
  g_t_best = t_best;
  g_end = vec4(0.0f);
  bool found = false;
  // The objects of the list of the reflector and direction cell the ray leaves by: those it can
  // reach (candidate_cells.h), a reflector's own maps in its own lists.
  int list = billboard_list_index(from, dir, u_billboard_cells);
  int listed = depthmap_lists[2 * list];
  for (int e = listed; e < listed + depthmap_lists[2 * list + 1]; ++e) {
    // The object's maps follow each other; the first holds their count.
    int first = depthmap_lists[e];
    int count = max(depthmaps[first].info.w, 1);
    // A reflector's own maps serve only the rays that leave it.
    int reflector = kSelfMaps ? instances[depthmaps[first].info.z].ids.y - 1 : -1;
    bool self = reflector >= 0;
    if (self && (reflector != from || !reflective)) continue;
    if (self) {
      g_impostor_candidates += 1;
      // The ray starts on the object, inside its maps' view: parts of it between a camera and
      // the origin hide what the ray hits from that camera, whichever way it looks. A hit found
      // in any map is a crossing of a surface that map sees, so every map is searched and the
      // nearest hit kept: more maps, fewer misses.
      for (int k = first; k < first + count; ++k)
        found = depthmap_search(depthmaps[k], true, origin, dir, t_min, g_t_best, dox, doy, ddx,
                                ddy, g_end) || found;
      continue;
    }
    // An object seen from outside: its maps in order of how nearly each camera looks along the
    // ray, until one is hit (depthmap_maps_shared.h); not at all when the ray passes its sphere
    // by, or meets it only beyond the nearest hit so far.
    g_impostor_candidates += 1;
    if (!depthmap_sphere_overlaps(origin, dir, depthmaps[first].bound, t_min, g_t_best)) continue;
    found = depthmap_object_search(dir, first, count, DEPTHMAP_TRIES) >= 0 || found;
  }
  t_best = g_t_best;
  end = g_end;
  return found;
}

bool impostor_extra_reflects(vec4 end, out vec3 normal, out int material, out int leaves) {
  normal = vec3(0.0f);
  material = -1;
  leaves = -1;
  if (!kSelfMaps) return false;
  int instance = depthmaps[int(end.z + 0.5f)].info.z;
  ivec4 ids = instances[instance].ids;
  if (ids.y <= 0) return false;
  normal = depthmap_normal(end.xyz, instance);
  material = ids.x;
  leaves = ids.y - 1;
  return true;
}

vec3 impostor_extra_radiance(vec4 end) {
  float lod = frame.options.y != 0 ? end.w : 0.0f;
  vec4 texel = textureLod(u_depthmap_color, end.xyz, lod);
  // Premultiplied by coverage: dividing by alpha averages the covered texels only.
  return texel.rgb / max(texel.a, 1.0e-4f);
}

#include "methods/impostor/impostor_trace.glsl"
