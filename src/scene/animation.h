// Rigid transforms and keyframed animation of instances.
#pragma once

#include <algorithm>
#include <cmath>
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

// Where `time` falls among keys of strictly increasing `.time` (wrapped into their span first
// when `loop`): between keys `a` and `b` = a + 1 at the fraction `u`; before the first key and
// after the last, a = b = that key. What instance animations and moving lights share.
struct KeySpan {
  size_t a = 0, b = 0;
  float u = 0.0f;
};
template <typename Key>
KeySpan keySpan(const std::vector<Key>& keys, float time, bool loop) {
  const float start = keys.front().time, end = keys.back().time;
  if (loop && end > start) {
    time = start + std::fmod(time - start, end - start);
    if (time < start) time += end - start;
  }
  if (keys.size() == 1 || time <= start) return {};
  if (time >= end) return {keys.size() - 1, keys.size() - 1, 0.0f};
  const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                     [](float t, const Key& k) { return t < k.time; });
  const size_t b = size_t(next - keys.begin());
  const float u = (time - keys[b - 1].time) / std::max(keys[b].time - keys[b - 1].time, 1e-9f);
  return {b - 1, b, u};
}

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
