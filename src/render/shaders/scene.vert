// Transforms one instance's mesh to world space for any scene pass.
#include "render/shaders/common.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;

layout(location = 0) uniform int u_instance;

out SurfaceData {
  vec3 world_position;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  flat int instance;
  // x: material; y: reflector id; z: albedo texture; w: normal map. Flat copies of buffer data:
  // on llvmpipe, helper invocations do not load from buffers, so anything that decides a branch
  // feeding a derivative (dFdx, implicit texture LOD) must come from a varying.
  flat ivec4 ids;
} v_out;

// One surface drawn by two programs (zexel's curved reflectors, then the base-colour pass that
// must fail the depth test at their pixels) gets one depth in both.
invariant gl_Position;

void main() {
  InstanceData inst = instances[u_instance];
  vec4 world = inst.model * vec4(a_position, 1.0f);
  v_out.world_position = world.xyz;
  v_out.normal = mat3(inst.normal_matrix) * a_normal;
  v_out.tangent = vec4(mat3(inst.model) * a_tangent.xyz, a_tangent.w);
  v_out.uv = a_uv;
  v_out.instance = u_instance;
  ivec4 kind = materials[inst.ids.x].kind;
  v_out.ids = ivec4(inst.ids.x, inst.ids.y, kind.y, kind.z);
  gl_Position = frame.view_proj * world;
}
