#include "support/depth_camera.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "raytrace/ray_scene.h"

namespace mirage {

View depthCamera(const vec3& centre, float radius, const vec3& from_direction, float fov_y_degrees,
                 int size) {
  CameraDesc desc = frameBounds(centre, radius, from_direction, fov_y_degrees);
  const float distance = glm::length(desc.position - centre);
  desc.near_plane = std::max(distance - radius, 1e-3f * distance);
  desc.far_plane = distance + radius;
  return View(desc, ivec2(size));
}

DepthMap traceDepthMap(const Scene& scene, int instance, float time, const View& camera) {
  // Only the instance: a scene holding it alone, so that nothing else occludes it.
  Scene alone = scene;
  alone.instances = {scene.instances[size_t(instance)]};
  RayScene rays(alone);
  rays.build(time);
  DepthMap map;
  map.size = camera.size().x;
  map.near = camera.nearPlane();
  map.far = camera.farPlane();
  map.depth.assign(size_t(map.size) * size_t(map.size), 1.0f);
  tbb::parallel_for(0, map.size, [&](int y) {
    for (int x = 0; x < map.size; ++x) {
      // Texel row y counts from the bottom; the view's pixel rows from the top.
      const Ray ray = camera.primaryRay(float(x) + 0.5f, float(map.size - y) - 0.5f);
      const RayHit hit = rays.intersect(ray);
      if (!hit.hit()) continue;
      const float z = hit.t * glm::dot(ray.direction, camera.forward());
      if (z <= map.near || z >= map.far) continue;
      map.depth[size_t(y) * size_t(map.size) + size_t(x)] =
          map.far * (z - map.near) / (z * (map.far - map.near));
    }
  });
  return map;
}

}  // namespace mirage
