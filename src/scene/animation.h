// Rigid transforms and keyframed animation of instances.
#pragma once

#include <vector>

#include "core/math.h"

namespace mirage {

struct Transform {
  vec3 translation{0.0f};
  quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
  vec3 scale{1.0f};

  mat4 matrix() const;
  bool operator==(const Transform& o) const = default;
};

struct Keyframe {
  float time = 0.0f;  // seconds
  Transform transform;
};

// Keyframes interpolated linearly (slerp for rotation); before the first key the first holds,
// after the last the last holds, or the animation repeats when `loop` is set.
struct Animation {
  std::vector<Keyframe> keys;  // sorted by time
  bool loop = false;

  bool empty() const { return keys.empty(); }
  float duration() const { return keys.empty() ? 0.0f : keys.back().time; }
  Transform at(float time) const;
};

}  // namespace mirage
