// Method `zexel`: the GPU warper. One point per zexel of a depth-preserving reflection map
// (gl_VertexID = row * width + column), moved by McMillan's warp (zexel_warp_shared.h) into the image
// seen from the mirrored eye and splatted as an s x s point; the depth test keeps the nearest.
// Zexels that saw the sky are skipped: the warped image's background is drawn from the
// mirrored eye itself.
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_warp_shared.h"

layout(binding = MIRAGE_UNIT_METHOD) uniform sampler2D u_zexels;  // rgb; a: distance along the ray

uniform mat4 u_pi;          // the map's pixel matrix (upper 3 x 3)
uniform mat4 u_po_inverse;  // the inverse of the output image's pixel matrix (upper 3 x 3)
uniform vec3 u_ci;          // the map's centre of projection
uniform vec3 u_co;          // the output's: the mirrored eye
uniform vec2 u_near_far_o;  // the output camera's near and far distances
uniform int u_width;        // zexels per row
uniform float u_splat;      // splat side in pixels

out vec4 v_color;  // rgb; a: distance from the mirrored eye

void main() {
  ivec2 texel = ivec2(gl_VertexID % u_width, gl_VertexID / u_width);
  vec4 zexel = texelFetch(u_zexels, texel, 0);
  gl_PointSize = u_splat;
  gl_Position = vec4(2.0f, 2.0f, 2.0f, 1.0f);  // outside the view: not drawn
  v_color = vec4(0.0f);
  if (!(zexel.a > 0.0f) || zexel.a >= 0.5f * MISS_DISTANCE) return;
  mat3 pi = mat3(u_pi);
  vec2 xi = vec2(texel) + 0.5f;
  float delta = zexel_disparity_from_distance(pi, xi, zexel.a);
  vec3 o = zexel_warp(mat3(u_po_inverse), pi, u_ci, u_co, delta, xi);
  if (!(o.z > 0.0f)) return;
  // A standard perspective depth for the depth test: the eye depth Z = w n_o.
  float n = u_near_far_o.x, f = u_near_far_o.y, z = o.z * n;
  vec2 ndc = 2.0f * o.xy / frame.viewport.xy - 1.0f;
  gl_Position = vec4(ndc * z, ((f + n) * z - 2.0f * f * n) / (f - n), z);
  vec3 point = u_ci + (pi * vec3(xi, 1.0f)) / delta;
  v_color = vec4(zexel.rgb, length(point - u_co));
}
