// The environment seen directly through each pixel centre: the primary ray of the ray tracer.
#include "render/shaders/common.glsl"

layout(location = 0) out vec4 out_color;
layout(location = 1) out uint out_id;

void main() {
  vec2 ndc = gl_FragCoord.xy / frame.viewport.xy * 2.0f - 1.0f;
  // The far plane's point of the pixel, homogeneous: w (X - eye) = X.xyz - eye X.w points along
  // the ray even when X lies behind the eye (w < 0), as on a mirrored view's oblique far plane.
  vec4 far_point = frame.inv_view_proj * vec4(ndc, 1.0f, 1.0f);
  vec3 direction = far_point.xyz - frame.eye.xyz * far_point.w;
  out_color = vec4(textureLod(u_environment, direction, 0.0f).rgb, MISS_DISTANCE);
  out_id = 0u;
}
