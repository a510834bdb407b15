// Method `zexel`: one level of a map's hierarchy from the finer one. A coarse zexel stands for
// the nearest of its four children — its distance — with the colour averaged over the children
// at about that depth (within 2 %), so that colours never bleed across a depth discontinuity.
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_IN, rgba32f) uniform readonly image2DArray u_in;
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, rgba32f) uniform writeonly image2DArray u_out;

uniform int u_width;  // the coarse level's zexels per row

void main() {
  ivec3 at = ivec3(gl_GlobalInvocationID);
  if (at.x >= u_width || at.y >= u_width) return;
  vec4 children[4];
  float nearest = MISS_DISTANCE * 2.0f;
  for (int i = 0; i < 4; ++i) {
    children[i] = imageLoad(u_in, ivec3(2 * at.xy + ivec2(i & 1, i >> 1), at.z));
    if (children[i].a > 0.0f) nearest = min(nearest, children[i].a);
  }
  vec3 sum = vec3(0.0f);
  float n = 0.0f;
  for (int i = 0; i < 4; ++i)
    if (children[i].a > 0.0f && children[i].a <= nearest * 1.02f) {
      sum += children[i].rgb;
      n += 1.0f;
    }
  imageStore(u_out, at, n > 0.0f ? vec4(sum / n, nearest) : vec4(0.0f));
}
