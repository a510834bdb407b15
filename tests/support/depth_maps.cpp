#include "support/depth_maps.h"

#include <algorithm>
#include <cmath>

namespace mirage::test {

DepthMap spheresDepthMap(int size, const std::vector<vec4>& spheres, float near, float far) {
  DepthMap map;
  map.size = size;
  map.near = near;
  map.far = far;
  map.depth.assign(size_t(size) * size_t(size), 1.0f);
  const float half = std::tan(glm::radians(20.0f));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const vec3 dir =
          glm::normalize(vec3((2.0f * (float(x) + 0.5f) / float(size) - 1.0f) * half,
                              (2.0f * (float(y) + 0.5f) / float(size) - 1.0f) * half, -1.0f));
      float best = 1e30f;
      for (const vec4& s : spheres) {
        const vec3 c(s);
        const float b = glm::dot(dir, c), disc = b * b - glm::dot(c, c) + s.w * s.w;
        if (disc < 0.0f) continue;
        const float t = b - std::sqrt(disc);
        if (t > 0.0f) best = std::min(best, t);
      }
      if (best >= 1e30f) continue;
      const float z = best * -dir.z;  // eye depth along the axis
      if (z <= near || z >= far) continue;
      map.depth[size_t(y) * size_t(size) + size_t(x)] = far * (z - near) / (z * (far - near));
    }
  return map;
}

DepthMap threeSpheresDepthMap(int size) {
  return spheresDepthMap(size, {vec4(0.0f, 0.0f, -3.0f, 0.8f), vec4(0.55f, 0.35f, -2.2f, 0.3f),
                                vec4(-0.7f, -0.6f, -3.5f, 0.25f)});
}

}  // namespace mirage::test
