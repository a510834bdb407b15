// Captures a reflector's depth map of itself (self-reflections): per texel the shading normal in
// the object's space, coverage in alpha. Stored in the object's space, the normal stays valid
// under any motion of the object; the reflector shader takes it to world space with the
// instance's normal matrix of the frame.
#include "render/shaders/surface.glsl"

void main() {
  // The world normal n_w = N n_o with N the inverse transpose of the model's 3x3 M, so
  // n_o = M^T n_w (up to length).
  mat3 model = mat3(instances[v_in.instance].model);
  out_color = vec4(normalize(transpose(model) * surface_normal()), 1.0f);
  out_id = 0u;
}
