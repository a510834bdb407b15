// The reflection probes of `envmap` and `envmap-box` looked up along a reflected ray: the pass
// that shades with them (those methods' reflector pass, `ssr`'s screen-space pass for the pixels
// its screen cannot show) includes this file, with PROBE_BOX defined for the box proxy (a
// parallax-corrected cube map), and binds them with render/probe_lookup.h. The probes' alpha
// holds the distance from their centre to what they saw (PROBE_SKY_DISTANCE or more for the
// sky: the half-float texture holds MISS_DISTANCE as its largest value or as +inf, by driver).
#include "render/shaders/probe_radiance.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_probes;

#ifdef PROBE_BOX
#include "shading/proxy.h"

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

// The radiance reaching `position` along `direction` as reflector `reflector`'s probe saw it
// (rgb, filtered by the direction's footprint dx, dy when mip-mapping is on), and the distance
// to what it saw (a; MISS_DISTANCE for the sky).
vec4 probe_lookup(vec3 position, vec3 direction, int reflector, vec3 dx, vec3 dy) {
  float layer = float(reflector - 1);
  vec3 lookup = direction;
#ifdef PROBE_BOX
  vec3 centre = probe_centre[reflector - 1].xyz;
  float t = -1.0f;
  vec3 corrected =
      u_proxy_sphere != 0
          ? sphere_parallax_direction(position, direction, u_sphere.xyz, u_sphere.w, centre, t)
          : box_parallax_direction(position, direction, u_box_min, u_box_max, centre, t);
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
#endif
  vec4 probe = probe_radiance(u_probes, lookup, layer, dx, dy);
#ifdef PROBE_BOX
  // The distance from the shaded point to what the probe saw along `lookup`.
  if (probe.a < PROBE_SKY_DISTANCE) {
    vec3 seen = centre + probe.a * normalize(lookup);
    return vec4(probe.rgb, length(seen - position));
  }
#endif
  if (probe.a >= PROBE_SKY_DISTANCE) probe.a = MISS_DISTANCE;
  return probe;
}
