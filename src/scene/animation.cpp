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
  const KeySpan span = keySpan(keys, time, loop);
  const Transform &a = keys[span.a].transform, &b = keys[span.b].transform;
  if (span.a == span.b) return a;
  Transform t;
  t.translation = glm::mix(a.translation, b.translation, span.u);
  t.rotation = glm::slerp(a.rotation, b.rotation, span.u);
  t.scale = glm::mix(a.scale, b.scale, span.u);
  return t;
}

}  // namespace mirage
