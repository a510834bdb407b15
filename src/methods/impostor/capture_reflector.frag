// Captures a reflective billboard: per texel the reflector's world-space shading normal with
// coverage in alpha (location 0) and the surface point with coverage in w (location 2; cleared
// to 0 elsewhere, so that a filtered lookup divided by w averages covered texels only), from
// which a ray that hits the billboard continues as a reflected ray of the next order.
#include "render/shaders/surface.glsl"

layout(location = 2) out vec4 out_position;

void main() {
  out_color = vec4(surface_normal(), 1.0f);
  out_id = 0u;
  out_position = vec4(v_in.world_position, 1.0f);
}
