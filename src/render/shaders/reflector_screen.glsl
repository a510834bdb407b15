// The reflector fragment stage as a screen-space pass (reflector.glsl under
// MIRAGE_REFLECTOR_SCREEN, drawn by ReflectorGBuffer::shade): one triangle over the viewport,
// shading the pixels whose G-buffer names a reflector — the method's own, the only ones drawn
// there — once each, after a single pass over the reflectors' triangles. The point comes from
// the depth buffer, the normal, material and reflector from the G-buffer (gbuffer.glsl); the
// differentials of the point and the reflected direction from the quad's neighbours on the same
// reflector. Writes the shaded colour only: the pass keeps the frame's alpha (the eye distance)
// and ids.
#include "render/shaders/reflection.glsl"
#include "render/shaders/gbuffer.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 g = texelFetch(u_gbuffer_normal, pixel, 0);
  vec3 p = gbuffer_world(vec3(gl_FragCoord.xy, texelFetch(u_gbuffer_depth, pixel, 0).r));
  vec3 n = octahedral_decode(vec2(g.x, g.y));
  vec3 to_viewer = normalize(frame.eye.xyz - p);
  vec3 r = reflect_direction(-to_viewer, n);
  gbuffer_differentials(r, g.w, g_dRdx, g_dRdy);
  gbuffer_differentials(p, g.w, g_dPdx, g_dPdy);
  if (!gbuffer_shades(g)) discard;  // not the draw's reflector
  MaterialData m = materials[int(g.z + 0.5f) - 1];
  vec4 reflected = reflected_radiance(p, r, n, int(g.w + 0.5f));
  float cos_theta = max(dot(n, to_viewer), 0.0f);
  out_color = vec4(shade_reflector(m, cos_theta, reflected.a, reflected.rgb), 0.0f);
}
