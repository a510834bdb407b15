// The depth-map camera and the ray-traced depth map: a tessellated mirror sphere against the
// analytic sphere, texel by texel.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/builtin_scenes.h"
#include "support/depth_camera.h"

namespace mirage {
namespace {

TEST(DepthCamera, TracedDepthOfASphereMatchesTheAnalyticSphere) {
  const Scene scene = makeBuiltinScene("sphere-over-checker");
  int sphere = -1;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == "mirror-sphere") sphere = int(i);
  ASSERT_GE(sphere, 0);
  const vec3 centre(0.0f, 1.25f, 0.0f);  // radius 1, 128 x 64 segments
  const Bounds3 bounds = scene.instanceBounds(sphere);
  const View camera =
      depthCamera(bounds.center(), bounds.radius(), vec3(1.0f, 0.5f, 2.0f), 30.0f, 96);
  // The planes enclose the bounding sphere: everything of the object is in the depth range.
  const float distance = glm::length(camera.eye() - bounds.center());
  EXPECT_NEAR(camera.nearPlane(), distance - bounds.radius(), 1e-4f);
  EXPECT_NEAR(camera.farPlane(), distance + bounds.radius(), 1e-4f);

  const DepthMap map = traceDepthMap(scene, sphere, 0.0f, camera);
  ASSERT_EQ(map.size, 96);
  int mismatched = 0, hits = 0;
  for (int y = 0; y < map.size; ++y)
    for (int x = 0; x < map.size; ++x) {
      const Ray ray = camera.primaryRay(float(x) + 0.5f, float(map.size - y) - 0.5f);
      const vec3 oc = ray.origin - centre;
      const float b = glm::dot(oc, ray.direction), disc = b * b - glm::dot(oc, oc) + 1.0f;
      const bool hit = disc >= 0.0f;
      const float d = map.at(x, y);
      if (hit != DepthMap::isForeground(d)) {
        ++mismatched;  // silhouette texels of the tessellation
        continue;
      }
      if (!hit) continue;
      ++hits;
      const float t = -b - std::sqrt(disc);
      const float z = t * glm::dot(ray.direction, camera.forward());
      // The 128 x 64 tessellation lies within 1.2e-3 of the sphere along the normal; along a
      // ray that meets the surface at a grazing angle that grows as 1 / cos.
      const vec3 normal = ray.origin + t * ray.direction - centre;
      const float cosine = std::abs(glm::dot(normal, ray.direction));
      EXPECT_NEAR(map.eyeDepth(d), z, 1.5e-3f / std::max(cosine, 0.05f))
          << "texel " << x << ", " << y;
    }
  EXPECT_GT(hits, 1500);
  EXPECT_LT(mismatched, hits / 50);
}

}  // namespace
}  // namespace mirage
