#include "methods/zexel/zexel_camera.h"

#include <algorithm>
#include <cmath>
#include <numeric>

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
  return zexelHemisphereView(point, normal, normal, half_diagonal, size, fov_y_degrees);
}

View zexelHemisphereView(const vec3& point, const vec3& normal, const vec3& w, float half_diagonal,
                         int size, float fov_y_degrees) {
  const vec3 n = glm::normalize(normal), d = glm::normalize(w);
  CameraDesc c;
  c.name = "zexel-reference";
  c.position = point - half_diagonal * d;
  c.target = point;
  c.up = std::abs(d.y) < 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(0.0f, 0.0f, 1.0f);
  c.fov_y_degrees = fov_y_degrees;
  c.near_plane = 1e-3f * half_diagonal;
  c.far_plane = 1e4f * half_diagonal;
  return View(c, ivec2(size, size)).clippedAt(point, n);
}

mat3 zexelMirrorFrame(const vec3& normal) {
  const vec3 z = glm::normalize(normal);
  const vec3 helper = std::abs(z.y) < 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
  const vec3 x = glm::normalize(glm::cross(helper, z));
  return mat3(x, glm::cross(z, x), z);
}

std::vector<vec3> zexelHemisphere(int count, float cone_degrees) {
  if (count <= 1) return {vec3(0.0f, 0.0f, 1.0f)};
  const float cos_cone = std::cos(glm::radians(std::clamp(cone_degrees, 0.0f, 89.0f)));
  const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
  std::vector<vec3> w;
  for (int k = 0; k < count; ++k) {
    // Equal steps in cos θ are equal areas on the sphere.
    const float cos_t = 1.0f - (1.0f - cos_cone) * (float(k) + 0.5f) / float(count);
    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
    const float phi = golden * float(k);
    w.emplace_back(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
  }
  return w;
}

std::vector<int> nearestZexelMaps(const std::vector<vec3>& directions, const vec3& point,
                                  const vec3& mirrored_eye, int count) {
  const vec3 seen = glm::normalize(point - mirrored_eye);
  std::vector<int> order(directions.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return glm::dot(directions[size_t(a)], seen) > glm::dot(directions[size_t(b)], seen);
  });
  order.resize(std::min(order.size(), size_t(std::max(count, 0))));
  return order;
}

}  // namespace mirage
