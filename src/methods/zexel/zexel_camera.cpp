#include "methods/zexel/zexel_camera.h"

#include <cmath>

namespace mirage {

mat3 zexelPixelMatrix(const View& view, float plane_distance) {
  const float t = view.tanHalfFovY(), a = view.aspect();
  const vec2 size = vec2(view.size());
  mat3 p;
  p[0] = plane_distance * (2.0f * t * a / size.x) * view.right();
  p[1] = plane_distance * (2.0f * t / size.y) * view.up();
  p[2] = plane_distance * (view.forward() - t * a * view.right() - t * view.up());
  return p;
}

View zexelReferenceView(const vec3& point, const vec3& normal, float half_diagonal, int size,
                        float fov_y_degrees) {
  const vec3 n = glm::normalize(normal);
  CameraDesc c;
  c.name = "zexel-reference";
  c.position = point - half_diagonal * n;
  c.target = point;
  c.up = std::abs(n.y) < 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(0.0f, 0.0f, 1.0f);
  c.fov_y_degrees = fov_y_degrees;
  c.near_plane = 1e-3f * half_diagonal;
  c.far_plane = 1e4f * half_diagonal;
  return View(c, ivec2(size, size)).clippedAt(point, n);
}

}  // namespace mirage
