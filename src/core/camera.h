// Pinhole cameras. CameraDesc is what a scene stores; View is a camera bound to an image size,
// with the matrices the rasterizer uses and the primary rays the ray tracer uses. Both follow the
// same convention, so that a GPU method and the ray tracer see pixel (x, y) through the same ray.
#pragma once

#include <string>

#include "core/camera_path.h"
#include "core/math.h"
#include "core/ray.h"

namespace mirage {

struct CameraDesc {
  std::string name = "default";
  vec3 position{0.0f, 1.0f, 5.0f};
  vec3 target{0.0f, 0.0f, 0.0f};
  vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;  // vertical field of view
  float near_plane = 0.05f;
  float far_plane = 1000.0f;
  // The image's width / height the camera was made for (a glTF camera's aspectRatio); 0: none, the
  // image's own. Only the default image size follows it: a View keeps fov_y whatever its size.
  float aspect = 0.0f;
  // Keyframes of position and target (a walk); empty for a still camera. A camera with a path
  // keeps its first key in `position` and `target`.
  CameraPath path;

  // This camera at scene time `time`: position and target from the path, itself without one.
  CameraDesc at(float time) const;
};

// Image pixels are addressed top-left first (row 0 is the top row), as in PNG files.
class View {
 public:
  View() = default;
  View(const CameraDesc& camera, ivec2 size);

  ivec2 size() const { return size_; }
  float aspect() const { return float(size_.x) / float(size_.y); }
  const vec3& eye() const { return eye_; }
  const vec3& forward() const { return forward_; }
  const vec3& right() const { return right_; }
  const vec3& up() const { return up_; }
  float tanHalfFovY() const { return tan_half_fov_y_; }
  float nearPlane() const { return near_; }
  float farPlane() const { return far_; }

  const mat4& viewMatrix() const { return view_; }
  const mat4& projectionMatrix() const { return projection_; }
  mat4 viewProjection() const { return projection_ * view_; }

  // The primary ray through image position (px, py), in pixels from the top-left corner
  // (pixel centres are at +0.5). Its direction is unit length.
  Ray primaryRay(float px, float py) const;

  // The pixel position (top-left origin) that a world point projects to; z is the view depth.
  vec3 project(const vec3& world) const;

  // This view seen in the planar mirror through `point` with unit `normal` (towards this view's
  // eye): the camera reflected in the plane, view matrix V·R with R the reflection (determinant
  // -1: windings flip), so that pixel (x, y) shows what this view sees at (x, y) in the mirror;
  // its near plane is the mirror plane (an oblique projection, Lengyel), so nothing behind the
  // mirror is drawn. Throws when the eye is not in front of the plane.
  View mirrored(const vec3& point, const vec3& normal) const;
  // This view with the plane through `point` with normal `normal` (pointing away from the eye,
  // towards what is kept) as its near plane: an oblique projection (Lengyel). Throws when the
  // eye is not behind the plane.
  View clippedAt(const vec3& point, const vec3& normal) const;

 private:
  ivec2 size_{1, 1};
  vec3 eye_{0.0f}, forward_{0.0f, 0.0f, -1.0f}, right_{1.0f, 0.0f, 0.0f}, up_{0.0f, 1.0f, 0.0f};
  float tan_half_fov_y_ = 0.41421356f;
  float near_ = 0.05f, far_ = 1000.0f;
  mat4 view_{1.0f}, projection_{1.0f};
};

// A camera that frames a bounding sphere from a direction, for scenes without one.
CameraDesc frameBounds(const vec3& center, float radius, const vec3& from_direction,
                       float fov_y_degrees = 40.0f);

}  // namespace mirage
