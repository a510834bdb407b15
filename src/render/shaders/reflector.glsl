// The reflector fragment stage shared by every method that shades reflectors per pixel.
// A method's shader includes this file and defines
//     vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector);
// returning the radiance arriving along the reflected ray (rgb) and the hit distance (a;
// MISS_DISTANCE when the ray leaves the scene). Defining MIRAGE_NO_REFLECTION before the include
// shades reflectors with their base colour (method `none`).
#include "render/shaders/surface.glsl"
#include "render/shaders/probe_radiance.glsl"

// Screen-space derivatives of the reflected direction, taken in uniform control flow so that
// methods can filter lookups (textureGrad) inside loops and branches.
vec3 g_dRdx = vec3(0.0f);
vec3 g_dRdy = vec3(0.0f);
// ... and of the shaded point: with the direction's, the reflected ray's differential.
vec3 g_dPdx = vec3(0.0f);
vec3 g_dPdy = vec3(0.0f);

// The scene's distant environment along `direction`, filtered by the reflected ray's footprint
// when mip-mapping is on.
vec3 environment_radiance(vec3 direction) {
  if (frame.options.y != 0) return textureGrad(u_environment, direction, g_dRdx, g_dRdy).rgb;
  return textureLod(u_environment, direction, 0.0f).rgb;
}

#ifndef MIRAGE_NO_REFLECTION
vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector);
#endif

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
