// Methods `envmap` (per-reflector probes), `envmap-box` (the same probes looked up through a box
// proxy of the room: a parallax-corrected cube map) and `envmap-infinite` (distant environment
// only). `envmap` looks the reflected ray up by direction alone, as if the reflected scene were
// infinitely far away. The probe's alpha holds the distance from its centre to what it saw
// (infinite for the sky: the half-float texture turns MISS_DISTANCE into +inf).
#include "render/shaders/reflector.glsl"

layout(binding = MIRAGE_UNIT_METHOD) uniform samplerCubeArray u_probes;

#ifdef ENVMAP_BOX
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

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
#ifdef ENVMAP_INFINITE
  return vec4(environment_radiance(direction), MISS_DISTANCE);
#else
  float layer = float(reflector - 1);
  vec3 lookup = direction;
  vec3 dx = g_dRdx, dy = g_dRdy;
#ifdef ENVMAP_BOX
  vec3 centre = probe_centre[reflector - 1].xyz;
  float t = -1.0f;
  vec3 corrected =
      u_proxy_sphere != 0
          ? sphere_parallax_direction(position, direction, u_sphere.xyz, u_sphere.w, centre, t)
          : box_parallax_direction(position, direction, u_box_min, u_box_max, centre, t);
  // Where the probe saw the sky along the corrected direction, the sky is at infinity and the
  // ray's own direction is exact; elsewhere the box point is the better guess.
  if (t >= 0.0f && textureLod(u_probes, vec4(corrected, layer), 0.0f).a < 0.5f * MISS_DISTANCE) {
    lookup = corrected;
    // The footprint seen from the probe: the ray's angular footprint scaled by the ratio of the
    // distance travelled (t) to the distance from the probe.
    float scale = t / max(length(corrected), 1.0e-6f);
    dx *= scale;
    dy *= scale;
  }
#endif
  vec4 probe = probe_radiance(u_probes, lookup, layer, dx, dy);
#ifdef ENVMAP_BOX
  // The distance from the shaded point to what the probe saw along `lookup`.
  if (probe.a < 0.5f * MISS_DISTANCE) {
    vec3 seen = centre + probe.a * normalize(lookup);
    return vec4(probe.rgb, length(seen - position));
  }
#endif
  return probe;
#endif
}
