#include "viewer/viewer_camera.h"

#include <algorithm>
#include <cmath>

namespace mirage {

namespace {
constexpr float kRadiansPerPixel = 0.005f;
constexpr float kPitchLimit = 1.55f;  // just short of straight up or down
}  // namespace

void ViewerCamera::reset(const CameraDesc& start) {
  base_ = start;
  base_.path = {};
  exact_ = base_;
  target_ = start.target;
  const vec3 offset = start.position - start.target;
  distance_ = std::max(glm::length(offset), 1e-4f);
  yaw_ = std::atan2(offset.x, offset.z);
  pitch_ = std::clamp(std::asin(std::clamp(offset.y / distance_, -1.0f, 1.0f)), -kPitchLimit,
                      kPitchLimit);
}

void ViewerCamera::orbit(vec2 delta) {
  if (delta == vec2(0.0f)) return;
  exact_.reset();
  yaw_ -= delta.x * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ + delta.y * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
}

void ViewerCamera::pan(vec2 delta, float height) {
  if (delta == vec2(0.0f)) return;
  const CameraDesc d = desc();
  exact_.reset();
  const vec3 forward = glm::normalize(d.target - d.position);
  const vec3 right = glm::normalize(glm::cross(forward, vec3(0.0f, 1.0f, 0.0f)));
  const vec3 up = glm::cross(right, forward);
  // One pixel moves the target by a pixel's size at the target's distance.
  const float per_pixel = 2.0f * distance_ * std::tan(glm::radians(base_.fov_y_degrees) * 0.5f) /
                          std::max(height, 1.0f);
  target_ += (-delta.x * right + delta.y * up) * per_pixel;
}

void ViewerCamera::dolly(float steps) {
  if (steps == 0.0f) return;
  exact_.reset();
  distance_ = std::max(distance_ * std::pow(0.9f, steps), 1e-3f);
}

void ViewerCamera::fly(vec3 direction, float speed, float seconds) {
  if (direction == vec3(0.0f) || speed * seconds == 0.0f) return;
  const CameraDesc d = desc();
  exact_.reset();
  const vec3 forward = glm::normalize(d.target - d.position);
  const vec3 right = glm::normalize(glm::cross(forward, vec3(0.0f, 1.0f, 0.0f)));
  target_ += (direction.x * right + direction.y * vec3(0.0f, 1.0f, 0.0f) + direction.z * forward) *
             (speed * seconds);
}

void ViewerCamera::frame(const Bounds3& bounds) {
  if (bounds.empty()) return;
  exact_.reset();
  target_ = bounds.center();
  const float radius = std::max(bounds.radius(), 1e-3f);
  distance_ = 1.1f * radius / std::sin(glm::radians(base_.fov_y_degrees) * 0.5f);
}

CameraDesc ViewerCamera::desc() const {
  if (exact_) return *exact_;
  CameraDesc d = base_;
  d.target = target_;
  d.position = target_ + distance_ * vec3(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
                                          std::cos(pitch_) * std::cos(yaw_));
  d.up = vec3(0.0f, 1.0f, 0.0f);
  return d;
}

}  // namespace mirage
