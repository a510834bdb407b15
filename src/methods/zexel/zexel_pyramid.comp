// Method `zexel`: one level of a map's hierarchy from the finer one (zexel_parent in
// zexel_splat_shared.h: the nearest child's distance, the colour of the children at its depth).
#include "render/shaders/common.glsl"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_IN, rgba32f) uniform readonly image2DArray u_in;
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, rgba32f) uniform writeonly image2DArray u_out;

uniform int u_width;  // the coarse level's zexels per row

void main() {
  ivec3 at = ivec3(gl_GlobalInvocationID);
  if (at.x >= u_width || at.y >= u_width) return;
  ivec2 child = 2 * at.xy;
  imageStore(u_out, at,
             zexel_parent(imageLoad(u_in, ivec3(child, at.z)),
                          imageLoad(u_in, ivec3(child + ivec2(1, 0), at.z)),
                          imageLoad(u_in, ivec3(child + ivec2(0, 1), at.z)),
                          imageLoad(u_in, ivec3(child + ivec2(1, 1), at.z))));
}
