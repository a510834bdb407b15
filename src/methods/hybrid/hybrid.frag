// Method `hybrid`: the reflector pass after the splats (the hybrid paper, §6–7). A pixel that a
// point reached shows that point, shaded with the shared diffuse model at its current place;
// any other pixel shows the background: the reflector's cube map of the scene without the
// point-sampled objects, looked up through the box proxy of what it shows (PROBE_BOX: the
// environment's parallax, as `envmap-box`). Fresnel and distance attenuation come from the
// shared reflector main.
#include "render/shaders/reflector.glsl"
#include "render/shaders/probe_lookup.glsl"
#include "methods/hybrid/hybrid_shared.h"

layout(std430, binding = MIRAGE_BIND_HYBRID_POINTS) readonly buffer PointBlock {
  vec4 positions[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_POINT_ATTRIBUTES) readonly buffer AttributeBlock {
  PointAttributes attributes[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_WINNERS) readonly buffer WinnerBlock {
  uint winners[];
};

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint word = winners[pixel.y * int(frame.viewport.x) + pixel.x];
  if (word != MIRAGE_HYBRID_EMPTY) {
    uint index = word & MIRAGE_HYBRID_INDEX_MASK;
    vec4 at = positions[index];  // object space; w: the instance
    PointAttributes p = attributes[index];
    InstanceData inst = instances[int(at.w)];
    vec3 q = (inst.model * vec4(at.xyz, 1.0f)).xyz;
    vec3 n = normalize(mat3(inst.normal_matrix) * p.normal.xyz);
    vec3 color = shade_diffuse(p.albedo.rgb, n, frame.light_dir.xyz, frame.light_color.rgb,
                               frame.ambient.rgb);
    return vec4(color, length(q - position));
  }
  return probe_lookup(position, direction, reflector, g_dRdx, g_dRdy);
}
