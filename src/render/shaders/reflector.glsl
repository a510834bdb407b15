// The reflector fragment stage shared by every method that shades reflectors per pixel.
// A method's shader includes this file and defines
//     vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector);
// returning the radiance arriving along the reflected ray (rgb) and the hit distance (a;
// MISS_DISTANCE when the ray leaves the scene). Defining MIRAGE_NO_REFLECTION before the include
// shades reflectors with their base colour (method `none`). Compiled with
// MIRAGE_REFLECTOR_SCREEN, the same shader is a screen-space pass over the reflector G-buffer
// (reflector_screen.glsl, under render/shaders/fullscreen.vert) instead of a pass over the
// reflectors' triangles.
// The include resolver expands every #include once, where it first appears, whatever the #if
// around it: what both passes need comes first, unconditionally.
#include "render/shaders/common.glsl"
#include "render/shaders/reflection.glsl"
#include "shading/octahedral.h"
#ifdef MIRAGE_REFLECTOR_SCREEN
#include "render/shaders/reflector_screen.glsl"
#else
#include "render/shaders/surface.glsl"

void main() {
  MaterialData m = surface_material();
  out_id = uint(v_in.ids.y);
#ifdef MIRAGE_NO_REFLECTION
  out_color = vec4(reflector_base(m), eye_distance());
  write_gbuffer(true);
#else
  vec3 p = v_in.world_position;
  vec3 to_viewer = normalize(frame.eye.xyz - p);
  vec3 geometric = cross(dFdx(p), dFdy(p));
  vec3 n = facing_normal(surface_normal(), geometric, to_viewer);
  vec3 r = reflect_direction(-to_viewer, n);
  g_dRdx = dFdx(r);
  g_dRdy = dFdy(r);
  g_dPdx = dFdx(p);
  g_dPdy = dFdy(p);
  vec4 reflected = reflected_radiance(p, r, n, v_in.ids.y);
  float cos_theta = max(dot(n, to_viewer), 0.0f);
  vec3 shaded = shade_reflector(m, cos_theta, reflected.a, reflected.rgb);
  out_color = vec4(shaded, eye_distance());
#endif
}
#endif
