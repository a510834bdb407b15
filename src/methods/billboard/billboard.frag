// Method `billboard`: the reflected scene replaced by billboards (the impostor paper, §3.1, and
// the order-K pixel algorithm of its slides, methods/impostor/impostor_trace.glsl). Cost
// O(K (D + R)) per pixel; the billboards live in storage buffers, so any number renders.
#include "render/shaders/reflector.glsl"
#include "methods/impostor/impostor_counts.glsl"

// Billboards only: no other impostors.
bool impostor_extra_hit(vec3 origin, vec3 dir, int from, bool reflective, float t_min,
                        inout float t_best, vec3 dox, vec3 doy, vec3 ddx, vec3 ddy, out vec4 end) {
  end = vec4(0.0f);
  return false;
}
bool impostor_extra_reflects(vec4 end, out vec3 normal, out int material, out int leaves) {
  normal = vec3(0.0f);
  material = -1;
  leaves = -1;
  return false;
}
vec3 impostor_extra_radiance(vec4 end) { return vec3(0.0f); }

#include "methods/impostor/impostor_trace.glsl"
