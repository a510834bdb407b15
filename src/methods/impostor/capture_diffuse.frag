// Captures a diffuse billboard: the object with the shared view-independent shading, alpha 1
// where it covers the texel (cleared to 0): colour is premultiplied, so mip-maps average only
// the covered texels' colours (rgb / a).
#include "render/shaders/surface.glsl"

void main() {
  MaterialData m = surface_material();
  vec3 color = shade_diffuse(surface_albedo(m), surface_normal(), frame.light_dir.xyz,
                             frame.light_color.rgb, frame.ambient.rgb);
  out_color = vec4(color, 1.0f);
  out_id = 0u;
}
