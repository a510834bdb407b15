#include "core/camera.h"

#include "core/error.h"

namespace mirage {

CameraDesc CameraDesc::at(float time) const {
  if (path.empty()) return *this;
  CameraDesc c = *this;
  CameraKey key = path.at(time);
  c.position = key.position;
  c.target = key.target;
  return c;
}

View::View(const CameraDesc& camera, ivec2 size) : size_(size) {
  if (size.x <= 0 || size.y <= 0) throwInput("view size {}x{} must be positive", size.x, size.y);
  eye_ = camera.position;
  vec3 to_target = camera.target - camera.position;
  if (glm::length(to_target) <= 0.0f)
    throwInput("camera '{}': position equals target", camera.name);
  forward_ = glm::normalize(to_target);
  vec3 r = glm::cross(forward_, camera.up);
  if (glm::length(r) < 1e-6f) {
    // Looking along the up vector: pick any perpendicular right vector.
    r = glm::cross(forward_, std::abs(forward_.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0));
  }
  right_ = glm::normalize(r);
  up_ = glm::cross(right_, forward_);
  tan_half_fov_y_ = std::tan(0.5f * radians(camera.fov_y_degrees));
  near_ = camera.near_plane;
  far_ = camera.far_plane;
  view_ = glm::lookAt(eye_, eye_ + forward_, up_);
  projection_ = glm::perspective(radians(camera.fov_y_degrees), aspect(), near_, far_);
}

Ray View::primaryRay(float px, float py) const {
  float ndc_x = 2.0f * px / float(size_.x) - 1.0f;
  float ndc_y = 1.0f - 2.0f * py / float(size_.y);
  vec3 d =
      forward_ + (ndc_x * tan_half_fov_y_ * aspect()) * right_ + (ndc_y * tan_half_fov_y_) * up_;
  return Ray{eye_, glm::normalize(d), 0.0f, kInfinity};
}

vec3 View::project(const vec3& world) const {
  vec4 clip = viewProjection() * vec4(world, 1.0f);
  vec3 ndc = vec3(clip) / clip.w;
  float depth = glm::dot(world - eye_, forward_);
  return vec3((ndc.x * 0.5f + 0.5f) * float(size_.x), (0.5f - ndc.y * 0.5f) * float(size_.y),
              depth);
}

View View::mirrored(const vec3& point, const vec3& normal) const {
  const vec3 n = glm::normalize(normal);
  const float offset = glm::dot(n, point);
  const float eye_side = glm::dot(n, eye_) - offset;
  if (!(eye_side > 0.0f)) throwRuntime("mirrored view: the eye is not in front of the mirror");
  // The reflection in the plane n·x = offset: x - 2 (n·x - offset) n.
  mat4 reflection(1.0f);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) reflection[c][r] -= 2.0f * n[c] * n[r];
  reflection[3] = vec4(2.0f * offset * n, 1.0f);
  View m = *this;
  m.eye_ = vec3(reflection * vec4(eye_, 1.0f));
  m.forward_ = glm::reflect(forward_, n);
  m.right_ = glm::reflect(right_, n);
  m.up_ = glm::reflect(up_, n);
  m.view_ = view_ * reflection;
  return m.clippedAt(point, n);
}

View View::clippedAt(const vec3& point, const vec3& normal) const {
  const vec3 n = glm::normalize(normal);
  if (!(glm::dot(n, point - eye_) > 0.0f))
    throwRuntime("clipped view: the eye is not behind the clipping plane");
  // Lengyel's oblique near plane: the plane (kept side along n) in camera space replaces the
  // near plane; the far plane follows obliquely.
  View m = *this;
  const vec4 plane_world(n, -glm::dot(n, point));
  const vec4 c = glm::transpose(glm::inverse(m.view_)) * plane_world;
  mat4& p = m.projection_;
  const vec4 q =
      glm::inverse(p) * vec4(c.x > 0.0f ? 1.0f : (c.x < 0.0f ? -1.0f : 0.0f),
                             c.y > 0.0f ? 1.0f : (c.y < 0.0f ? -1.0f : 0.0f), 1.0f, 1.0f);
  const vec4 scaled = c * (2.0f / glm::dot(c, q));
  for (int col = 0; col < 4; ++col) p[col][2] = scaled[col] - p[col][3];
  return m;
}

CameraDesc frameBounds(const vec3& center, float radius, const vec3& from_direction,
                       float fov_y_degrees) {
  CameraDesc c;
  float distance = radius / std::sin(0.5f * radians(fov_y_degrees)) * 1.1f;
  c.position = center + glm::normalize(from_direction) * distance;
  c.target = center;
  c.fov_y_degrees = fov_y_degrees;
  c.near_plane = std::max(1e-3f, 0.01f * radius);
  c.far_plane = distance + 100.0f * radius;
  return c;
}

}  // namespace mirage
