#include "scene/animation.h"

#include <algorithm>
#include <cmath>

namespace mirage {

mat4 Transform::matrix() const {
  return glm::translate(mat4(1.0f), translation) * glm::mat4_cast(rotation) *
         glm::scale(mat4(1.0f), scale);
}

Transform Animation::at(float time) const {
  if (keys.empty()) return {};
  if (keys.size() == 1) return keys.front().transform;
  float start = keys.front().time, end = keys.back().time;
  if (loop && end > start) {
    time = start + std::fmod(time - start, end - start);
    if (time < start) time += end - start;
  }
  if (time <= start) return keys.front().transform;
  if (time >= end) return keys.back().transform;
  auto next = std::upper_bound(keys.begin(), keys.end(), time,
                               [](float t, const Keyframe& k) { return t < k.time; });
  const Keyframe& b = *next;
  const Keyframe& a = *(next - 1);
  float u = (time - a.time) / std::max(b.time - a.time, 1e-9f);
  Transform t;
  t.translation = glm::mix(a.transform.translation, b.transform.translation, u);
  t.rotation = glm::slerp(a.transform.rotation, b.transform.rotation, u);
  t.scale = glm::mix(a.transform.scale, b.transform.scale, u);
  return t;
}

}  // namespace mirage
