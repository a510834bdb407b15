// Runs the proxy intersections of shading/proxy.h on the GPU for a list of cases, so that a test
// can check that the GLSL compile of the shared header gives what its C++ compile gives.
#include "shading/proxy.h"

layout(local_size_x = 64) in;

struct ProxyCase {
  vec4 origin;  // xyz
  vec4 dir;     // xyz
  vec4 a;       // box min / quad corner
  vec4 b;       // box max / quad edge u
  vec4 c;       // probe centre / quad edge v
  vec4 morph;   // x: height, y: wall height
};

struct ProxyResult {
  vec4 box;       // x: ray_box_exit t; y: face
  vec4 quad;      // x: ray_quad t; yz: uv
  vec4 parallax;  // xyz: box_parallax_direction; w: its t
  vec4 morph;     // xyz: morph_direction
  vec4 sphere;    // x: ray_sphere_exit (centre c, radius morph.y)
};

layout(std430, binding = 0) readonly buffer Cases { ProxyCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { ProxyResult results[]; };
uniform int u_count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  ProxyCase k = cases[i];
  ProxyResult r;
  int face = -1;
  r.box = vec4(ray_box_exit(k.origin.xyz, k.dir.xyz, k.a.xyz, k.b.xyz, face), float(face), 0, 0);
  vec2 uv = vec2(-1.0f);
  float t = ray_quad(k.origin.xyz, k.dir.xyz, k.a.xyz, k.b.xyz, k.c.xyz, 0.0f, uv);
  r.quad = vec4(t, uv, 0.0f);
  float tp = 0.0f;
  vec3 d = box_parallax_direction(k.origin.xyz, k.dir.xyz, k.a.xyz, k.b.xyz, k.c.xyz, tp);
  r.parallax = vec4(d, tp);
  r.morph = vec4(morph_direction(k.b.xyz, k.c.xyz, k.dir.xyz, k.morph.x, k.morph.y), 0.0f);
  r.sphere = vec4(ray_sphere_exit(k.origin.xyz, k.dir.xyz, k.c.xyz, k.morph.y), 0, 0, 0);
  results[i] = r;
}
