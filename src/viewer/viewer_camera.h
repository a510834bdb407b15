// The viewer's camera: orbit about a target (left drag), pan (right or middle drag), dolly
// (wheel), fly (WASD + QE move eye and target together), frame a box (F), starting from a scene
// camera; R returns to it. The eye keeps its pitch short of straight up or down, so that every
// camera it gives can be written to a camera file and read back.
#pragma once

#include <optional>

#include "core/bounds.h"
#include "core/camera.h"

namespace mirage {

class ViewerCamera {
 public:
  explicit ViewerCamera(const CameraDesc& start) { reset(start); }

  void reset(const CameraDesc& start);
  // Mouse motion in pixels.
  void orbit(vec2 delta_pixels);
  void pan(vec2 delta_pixels, float viewport_height);
  // Wheel steps: positive moves toward the target (never through it).
  void dolly(float steps);
  // Moves eye and target along the view's right (x), the world's up (y) and the view's forward
  // (z) by `direction` (each -1..1) at `speed` units per second for `seconds`.
  void fly(vec3 direction, float speed, float seconds);
  // Looks at the centre of `bounds` from the current direction, at the distance that fits its
  // bounding sphere in the view.
  void frame(const Bounds3& bounds);

  CameraDesc desc() const;
  float distance() const { return distance_; }

 private:
  CameraDesc base_;
  // The camera given to reset(), until the user moves it: shown as it is, so that a scene's
  // camera or a played path's is render's to the bit (the orbit's angles round it, and its up is
  // the world's).
  std::optional<CameraDesc> exact_;
  vec3 target_{0.0f};
  float distance_ = 1.0f, yaw_ = 0.0f, pitch_ = 0.0f;  // radians; the eye relative to the target
};

}  // namespace mirage
