// The reflection probes of `envmap` and `envmap-box` looked up along a reflected ray: the pass
// that shades with them (those methods' reflector pass, `ssr`'s screen-space pass for the pixels
// its screen cannot show) includes this file, with PROBE_BOX defined for the box proxy (a
// parallax-corrected cube map) and PROBE_BLEND for a scene's own probes (scene/probes.h: blended
// by position, each with its proxy) instead of one probe per reflector, and binds them with
// render/probe_lookup.h. The probes' alpha holds the distance from their centre to what they saw
// (PROBE_SKY_DISTANCE or more for the sky: the half-float texture holds MISS_DISTANCE as its
// largest value or as +inf, by driver).
#include "render/shaders/probe_radiance.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_probes;

#if defined(PROBE_BOX) || defined(PROBE_BLEND)
#include "shading/proxy.h"
#endif

#ifdef PROBE_BLEND
#include "shading/probe_blend.h"
// A scene's probes (scene/probes.h), in blend order: any reflector's point takes them in turn.
// Read for values only (see docs/architecture.md on helper invocations).
layout(std430, binding = MIRAGE_BIND_METHOD_SSBO) readonly buffer ProbeVolumes {
  ProbeVolumeData probe_volume[];
};
uniform int u_probe_count;
// The work of one lookup is bounded: the probes walked (a scene has at most 32) and the cube
// lookups blended (a point in more than PROBE_MAX_BLENDED probes' volumes takes the first).
#define PROBE_MAX_COUNT 32
#define PROBE_MAX_BLENDED 4
#elif defined(PROBE_BOX)
uniform vec3 u_box_min;
uniform vec3 u_box_max;
uniform int u_proxy_sphere;  // 1: Bjorke's sphere proxy (the box's circumscribed sphere)
uniform vec4 u_sphere;       // xyz: centre; w: radius
// Probe centre per reflector (index reflector id - 1). Read for values only: no derivative is
// taken of anything computed from it (see docs/architecture.md on helper invocations).
layout(std430, binding = MIRAGE_BIND_METHOD_SSBO) readonly buffer ProbeCentres {
  vec4 probe_centre[];
};
#endif

#if defined(PROBE_BOX) || defined(PROBE_BLEND)
// Cube `layer`, captured at `centre`, along `direction` from `position` corrected for parallax
// through a proxy: the sphere (sphere_c, sphere_r) when `sphere` is set, else the box
// [bmin, bmax]; the distance from `position` to what the probe saw.
vec4 probe_parallax_lookup(vec3 position, vec3 direction, float layer, vec3 centre, bool sphere,
                           vec3 bmin, vec3 bmax, vec3 sphere_c, float sphere_r, vec3 dx,
                           vec3 dy) {
  vec3 lookup = direction;
  float t = -1.0f;
  vec3 corrected = sphere
                       ? sphere_parallax_direction(position, direction, sphere_c, sphere_r, centre, t)
                       : box_parallax_direction(position, direction, bmin, bmax, centre, t);
  // The box point, wherever the ray leaves the box: also where the probe saw the sky there (a
  // test for the sky here would depend on how the driver stores MISS_DISTANCE in a half float;
  // a proxy open where nothing bounds the scene — hybrid's — sends such rays far, along their
  // own direction).
  if (t >= 0.0f) {
    lookup = corrected;
    // The footprint seen from the probe: the ray's angular footprint scaled by the ratio of the
    // distance travelled (t) to the distance from the probe.
    float scale = t / max(length(corrected), 1.0e-6f);
    dx *= scale;
    dy *= scale;
  }
  vec4 probe = probe_radiance(u_probes, lookup, layer, dx, dy);
  // The distance from the shaded point to what the probe saw along `lookup`.
  if (probe.a < PROBE_SKY_DISTANCE) {
    vec3 seen = centre + probe.a * normalize(lookup);
    return vec4(probe.rgb, length(seen - position));
  }
  return vec4(probe.rgb, MISS_DISTANCE);
}
#endif

#ifdef PROBE_BLEND
// The scene's probes blended at `position` (shading/probe_blend.h): each takes its share of what
// the probes before it left, the distant environment the rest; the distance is the largest
// share's. `reflector` plays no part: a scene's probes are shared by every reflector.
vec4 probe_lookup(vec3 position, vec3 direction, int reflector, vec3 dx, vec3 dy) {
  vec3 rgb = vec3(0.0f);
  float taken = 0.0f, largest = 0.0f, distance = MISS_DISTANCE;
  int blended = 0;
  for (int i = 0; i < min(u_probe_count, PROBE_MAX_COUNT); ++i) {
    if (taken >= 1.0f || blended == PROBE_MAX_BLENDED) break;
    ProbeVolumeData v = probe_volume[i];
    float weight =
        v.influence_hi.w > 0.0f
            ? probe_sphere_weight(position, v.influence_lo.xyz, v.influence_hi.w, v.influence_lo.w)
            : probe_box_weight(position, v.influence_lo.xyz, v.influence_hi.xyz, v.influence_lo.w);
    float share = probe_blend_share(weight, taken);
    if (share <= 0.0f) continue;
#ifdef PROBE_BOX
    vec4 seen = probe_parallax_lookup(position, direction, v.position.w, v.position.xyz,
                                      v.proxy_hi.w > 0.0f, v.proxy_lo.xyz, v.proxy_hi.xyz,
                                      v.proxy_lo.xyz, v.proxy_hi.w, dx, dy);
#else
    vec4 seen = probe_radiance(u_probes, direction, v.position.w, dx, dy);
    if (seen.a >= PROBE_SKY_DISTANCE) seen.a = MISS_DISTANCE;
#endif
    rgb += share * seen.rgb;
    taken += share;
    if (share > largest) {
      largest = share;
      distance = seen.a;
    }
    ++blended;
  }
  rgb += max(1.0f - taken, 0.0f) * environment_lookup(direction, dx, dy);
  return vec4(rgb, distance);
}
#else
// The radiance reaching `position` along `direction` as reflector `reflector`'s probe saw it
// (rgb, filtered by the direction's footprint dx, dy when mip-mapping is on), and the distance
// to what it saw (a; MISS_DISTANCE for the sky).
vec4 probe_lookup(vec3 position, vec3 direction, int reflector, vec3 dx, vec3 dy) {
  float layer = float(reflector - 1);
#ifdef PROBE_BOX
  return probe_parallax_lookup(position, direction, layer, probe_centre[reflector - 1].xyz,
                               u_proxy_sphere != 0, u_box_min, u_box_max, u_sphere.xyz,
                               u_sphere.w, dx, dy);
#else
  vec4 probe = probe_radiance(u_probes, direction, layer, dx, dy);
  if (probe.a >= PROBE_SKY_DISTANCE) probe.a = MISS_DISTANCE;
  return probe;
#endif
}
#endif
