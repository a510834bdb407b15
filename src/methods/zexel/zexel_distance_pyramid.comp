// Method `zexel`, curved reflectors: one step of the distance pyramid's build
// (zexel_distance_pyramid.h, zexel_bounds_shared.h), chosen by ZEXEL_PYRAMID_STEP:
//   0: level 0, the cube maps' distances (alpha), into the pyramid and the reductions;
//   1: M_L, the least of the four M_(L−1) texels it covers (r), and their farthest finite
//      distance (g: 0 for none);
//   2: B_L, the least M_L within ZEXEL_BOUND_DILATION texels (zexel_bound_texel), the pyramid's
//      level L;
//   3: each cube's farthest finite distance, from the reductions' coarsest level.
// One invocation a texel of one face of one cube (z: 6 · cube + face); step 3: one a cube.
#include "render/shaders/common.glsl"
#if ZEXEL_PYRAMID_STEP == 2
#define ZEXEL_BOUNDS_BUILD  // zexel_bound_texel, over zexel_reduced_distance below
float zexel_reduced_distance(int layer, vec3 direction, int level);
#endif
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_bounds_shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

uniform int u_width;  // texels across a face at the level written
uniform int u_level;  // the level written (step 2)

#if ZEXEL_PYRAMID_STEP == 0
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_IN, rgba32f) uniform readonly imageCubeArray u_cubes;
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, r32f) uniform writeonly imageCubeArray u_out;
layout(binding = MIRAGE_IMAGE_ZEXEL_REDUCED, rg32f) uniform writeonly imageCubeArray u_reduced;
#elif ZEXEL_PYRAMID_STEP == 1
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_IN, rg32f) uniform readonly imageCubeArray u_in;
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, rg32f) uniform writeonly imageCubeArray u_out;
#elif ZEXEL_PYRAMID_STEP == 3
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_IN, rg32f) uniform readonly imageCubeArray u_in;
layout(std430, binding = MIRAGE_BIND_ZEXEL_FAR) writeonly buffer FarBlock { float far_distance[]; };
uniform int u_cubes;
#else
layout(binding = MIRAGE_UNIT_ZEXEL_REDUCED) uniform samplerCubeArray u_reduced;  // nearest
layout(binding = MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, r32f) uniform writeonly imageCubeArray u_out;

float zexel_reduced_distance(int layer, vec3 direction, int level) {
  return textureLod(u_reduced, vec4(direction, float(layer)), float(level)).r;
}
#endif

#if ZEXEL_PYRAMID_STEP == 1
// The least distance and the farthest finite one of two reductions.
vec2 zexel_merge(vec2 a, vec2 b) { return vec2(min(a.x, b.x), max(a.y, b.y)); }
#endif

void main() {
  ivec3 at = ivec3(gl_GlobalInvocationID);
#if ZEXEL_PYRAMID_STEP == 3
  if (at.x >= u_cubes || at.y > 0 || at.z > 0) return;
  float farthest = 0.0f;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < u_width; ++y)
      for (int x = 0; x < u_width; ++x)
        farthest = max(farthest, imageLoad(u_in, ivec3(x, y, 6 * at.x + face)).g);
  far_distance[at.x] = farthest;
#else
  if (at.x >= u_width || at.y >= u_width) return;
#endif
#if ZEXEL_PYRAMID_STEP == 0
  float distance = imageLoad(u_cubes, at).a;
  imageStore(u_out, at, vec4(distance));
  imageStore(u_reduced, at, vec4(distance, distance < ZEXEL_SKY_DISTANCE ? distance : 0.0f, 0, 0));
#elif ZEXEL_PYRAMID_STEP == 1
  ivec2 child = 2 * at.xy;
  vec2 merged = zexel_merge(zexel_merge(imageLoad(u_in, ivec3(child, at.z)).rg,
                                        imageLoad(u_in, ivec3(child + ivec2(1, 0), at.z)).rg),
                            zexel_merge(imageLoad(u_in, ivec3(child + ivec2(0, 1), at.z)).rg,
                                        imageLoad(u_in, ivec3(child + ivec2(1, 1), at.z)).rg));
  imageStore(u_out, at, vec4(merged, 0.0f, 0.0f));
#elif ZEXEL_PYRAMID_STEP == 2
  imageStore(u_out, at,
             vec4(zexel_bound_texel(at.z / 6, at.z % 6, at.xy, u_level, u_width)));
#endif
}
