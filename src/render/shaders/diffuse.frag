// Diffuse surfaces: the shared view-independent shading.
#include "render/shaders/surface.glsl"

void main() {
  MaterialData m = surface_material();
  vec3 color = shade_diffuse(surface_albedo(m), surface_normal(), frame.light_dir.xyz,
                             frame.light_color.rgb, frame.ambient.rgb);
  out_color = vec4(color, eye_distance());
  out_id = 0u;
  write_gbuffer(false);
}
