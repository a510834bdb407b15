// The viewer's camera: orbit about a target (left drag), pan (right or middle drag), dolly
// (wheel), starting from a scene camera; R returns to it.
#pragma once

#include "core/camera.h"

namespace mirage {

class OrbitCamera {
 public:
  explicit OrbitCamera(const CameraDesc& start) { reset(start); }

  void reset(const CameraDesc& start);
  // Mouse motion in pixels over a viewport `height` pixels tall.
  void orbit(vec2 delta_pixels);
  void pan(vec2 delta_pixels, float height);
  // Wheel steps: positive moves toward the target (never through it).
  void dolly(float steps);

  CameraDesc desc() const;

 private:
  CameraDesc base_;
  vec3 target_{0.0f};
  float distance_ = 1.0f, yaw_ = 0.0f, pitch_ = 0.0f;  // radians; the eye relative to the target
};

}  // namespace mirage
