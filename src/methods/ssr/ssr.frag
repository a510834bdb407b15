// Method `ssr`: screen-space reflections, a screen-space pass over the reflector pixels of the
// frame's G-buffer (one triangle over the viewport; the reflectors are not drawn again). Each
// reflector pixel's point comes from the depth buffer and its normal, material and reflector
// from the G-buffer; its reflected ray marches the hierarchical-Z pyramid of the direct view's
// depth (ssr_march_shared.h) and, where it hits a surface seen from its front, shows the direct
// view's colour there; its weight fades to 0 near the screen's edges. Rays that leave the
// screen, hit nothing, hit a back face or run out of steps get weight 0. Where the weight is
// below 1 the fallback's probe (render/shaders/probe_lookup.glsl; PROBE_BOX for envmap-box)
// makes up the rest: the pixel is the weight's mix of the two, each shaded with the shared
// model. The frame's alpha (the eye distance) and ids are kept.
#include "render/shaders/common.glsl"
#include "methods/ssr/ssr_shared.h"
#include "render/shaders/counter_slots.glsl"
#include "render/shaders/probe_lookup.glsl"
#include "render/shaders/gbuffer.glsl"

layout(location = 0) out vec4 out_color;

layout(binding = MIRAGE_UNIT_SSR_HIZ) uniform sampler2D u_hiz;
layout(binding = MIRAGE_UNIT_SSR_COLOR) uniform sampler2D u_color;
layout(std430, binding = MIRAGE_BIND_SSR_COUNTS) buffer SsrCounts {
  uint ssr_counts[MIRAGE_COUNTER_SLOTS * MIRAGE_COUNTER_SLOT_WORDS];
};

uniform ivec2 u_size;       // the screen in pixels
uniform int u_levels;       // levels of the pyramid
uniform int u_max_steps;    // --ssr-steps
uniform float u_edge_fade;  // --ssr-edge-fade: the fade's width, a fraction of the shorter side
uniform float u_near;
uniform float u_far;
uniform vec3 u_forward;  // the view direction (world)
uniform int u_beyond_probe;  // 1: a hit on a reflector shows its probe (--beyond-order probe)

// The pyramid, level 0 the depth buffer's copy (hiz_pyramid.h): r the nearest depth, g the
// behind limit of the farthest drawn. The march never leaves the padded pyramid: its ray is
// clipped to the screen.
vec2 ssr_cell(int level, int x, int y) { return texelFetch(u_hiz, ivec2(x, y), level).rg; }

#include "methods/ssr/ssr_march_shared.h"

float g_coverage = 0.0f;  // the weight of the screen's reflection at this pixel

vec3 to_window(vec3 world) {
  vec4 clip = frame.view_proj * vec4(world, 1.0f);
  vec3 ndc = clip.xyz / clip.w;
  return vec3((ndc.xy * 0.5f + 0.5f) * vec2(u_size), ndc.z * 0.5f + 0.5f);
}


// One atomic a pixel (and one more in the fade), into the pixel's slot (counter_slots.glsl): the
// pixel count and the fallback's whole pixels are sums of these on the CPU.
void count(int which) { atomicAdd(ssr_counts[counter_slot() + which], 1u); }

// What a hit at window position `at` (world point `hit`, met along `direction`) shows when the
// G-buffer holds a reflector there: that reflector shaded with its probe along the ray reflected
// again (the second bounce, beyond ssr's order), instead of the base colour the direct view drew
// it in (`base`). The hit's footprint is not known here: the probe is read unfiltered.
vec3 beyond_order_radiance(vec2 at, vec3 hit, vec3 direction, vec3 base) {
  vec4 g = texelFetch(u_gbuffer_normal, clamp(ivec2(at), ivec2(0), u_size - 1), 0);
  if (g.z < 0.5f) return base;
  vec3 n = octahedral_decode(g.xy);
  vec4 probe = probe_lookup(hit, reflect_direction(direction, n), int(g.w + 0.5f), vec3(0.0f),
                            vec3(0.0f));
  MaterialData m = materials[int(g.z + 0.5f) - 1];
  return shade_reflector(m, max(dot(n, -direction), 0.0f), probe.a, probe.rgb);
}

// The radiance along the reflected ray from the pixel at `from` (window coordinates; `position` in
// the world) and the hit's distance; g_coverage its weight.
vec4 reflected_radiance(vec3 from, vec3 position, vec3 direction) {
  g_coverage = 0.0f;
  // The ray in the world, cut where it would cross the near plane (towards the eye) or pass
  // the far plane, then projected and cut at the screen's edges.
  float depth0 = dot(position - frame.eye.xyz, u_forward);
  float rate = dot(direction, u_forward);
  float length_max = 2.0f * u_far;
  if (rate < 0.0f) length_max = min(length_max, (depth0 - 1.001f * u_near) / -rate);
  if (rate > 0.0f) length_max = min(length_max, (0.999f * u_far - depth0) / rate);
  vec3 to = to_window(position + max(length_max, 0.0f) * direction);
  vec2 d = to.xy - from.xy;
  float t_screen = 1.0f;
  vec2 lo = vec2(0.0f), hi = vec2(u_size) - 1.0e-3f;
  if (d.x > 0.0f) t_screen = min(t_screen, (hi.x - from.x) / d.x);
  if (d.x < 0.0f) t_screen = min(t_screen, (lo.x - from.x) / d.x);
  if (d.y > 0.0f) t_screen = min(t_screen, (hi.y - from.y) / d.y);
  if (d.y < 0.0f) t_screen = min(t_screen, (lo.y - from.y) / d.y);
  t_screen = max(t_screen, 0.0f);
  to = from + t_screen * (to - from);

  ivec2 pixel;
  int steps;
  float t = ssr_march(from, to, u_levels, u_max_steps, pixel, steps);
  atomicAdd(ssr_counts[counter_slot() + MIRAGE_SSR_STEPS], uint(steps));
  if (t < 0.0f) {
    if (steps >= u_max_steps)
      count(MIRAGE_SSR_OUT_OF_STEPS);
    else if (t_screen < 1.0f)
      count(MIRAGE_SSR_OFF_SCREEN);
    else
      count(MIRAGE_SSR_NO_HIT);
  } else if (dot(octahedral_decode(texelFetch(u_gbuffer_normal, pixel, 0).xy), direction) > 0.0f) {
    count(MIRAGE_SSR_BACK_FACE);
  } else {
    float exit_t = ssr_cell_exit(from, to, t, 1.0f);
    float refined = ssr_refine(from, to, t, exit_t, u_size, 6);
    vec3 at = from + refined * (to - from);
    float edge = min(min(at.x, float(u_size.x) - at.x), min(at.y, float(u_size.y) - at.y));
    float fade_width = u_edge_fade * float(min(u_size.x, u_size.y));
    g_coverage = fade_width > 0.0f ? clamp(edge / fade_width, 0.0f, 1.0f) : 1.0f;
    if (g_coverage >= 1.0f) {
      count(MIRAGE_SSR_HITS);
    } else {
      count(MIRAGE_SSR_FADED);
      atomicAdd(ssr_counts[counter_slot() + MIRAGE_SSR_FADED_WEIGHT],
                uint((1.0f - g_coverage) * 1024.0f + 0.5f));
    }
    vec3 hit = gbuffer_world(vec3(at.xy, ssr_bilinear_depth(at.xy, u_size)));
    vec3 colour = textureLod(u_color, at.xy / vec2(u_size), 0.0f).rgb;
    if (u_beyond_probe != 0) colour = beyond_order_radiance(at.xy, hit, direction, colour);
    return vec4(colour, length(hit - position));
  }
  return vec4(0.0f, 0.0f, 0.0f, MISS_DISTANCE);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 g = texelFetch(u_gbuffer_normal, pixel, 0);
  vec3 window = vec3(gl_FragCoord.xy, texelFetch(u_hiz, pixel, 0).r);
  vec3 p = gbuffer_world(window);
  vec3 n = octahedral_decode(g.xy);
  vec3 to_viewer = normalize(frame.eye.xyz - p);
  vec3 r = reflect_direction(-to_viewer, n);
  vec3 dx, dy;
  gbuffer_differentials(r, g.w, dx, dy);
  if (!gbuffer_shades(g)) discard;  // not the draw's reflector
  MaterialData m = materials[int(g.z + 0.5f) - 1];
  vec4 reflected = reflected_radiance(window, p, r);
  float cos_theta = max(dot(n, to_viewer), 0.0f);
  vec3 shaded = vec3(0.0f);
  if (g_coverage > 0.0f) shaded = shade_reflector(m, cos_theta, reflected.a, reflected.rgb);
  if (g_coverage < 1.0f) {
    vec4 probe = probe_lookup(p, r, int(g.w + 0.5f), dx, dy);
    shaded = mix(shade_reflector(m, cos_theta, probe.a, probe.rgb), shaded, g_coverage);
  }
  out_color = vec4(shaded, 0.0f);  // alpha masked: the eye distance stays
}
