// Method `hybrid`: which reflector triangle each pixel sees (instance + 1, primitive), read back
// so that C3RCs are built only for triangles with visible pixels — hidden and back-facing parts
// of a closed reflector cost nothing, and triangles below the pixel threshold fall back to the
// environment (the hybrid paper's §7 remedy for the teapot's knob).
#include "render/shaders/common.glsl"

in SurfaceData {
  vec3 world_position;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  flat int instance;
  flat ivec4 ids;
} v_in;

layout(location = 0) out uvec2 out_triangle;

void main() {
  out_triangle = uvec2(uint(v_in.instance) + 1u, uint(gl_PrimitiveID));
}
