#include "core/camera_path.h"

#include <algorithm>

namespace mirage {

namespace {

// The tangent (units per second) at key i: central difference over the neighbours, one-sided
// at the ends.
vec3 tangent(const std::vector<CameraKey>& keys, size_t i, vec3 CameraKey::*field) {
  size_t lo = i == 0 ? 0 : i - 1, hi = std::min(i + 1, keys.size() - 1);
  float dt = keys[hi].time - keys[lo].time;
  return dt > 0.0f ? (keys[hi].*field - keys[lo].*field) / dt : vec3(0.0f);
}

// Cubic Hermite between key a and key b at u in [0, 1]; `h` is the segment's length in seconds.
vec3 hermite(const std::vector<CameraKey>& keys, size_t a, float u, float h,
             vec3 CameraKey::*field) {
  const float u2 = u * u, u3 = u2 * u;
  const float h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
  const float h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  return h00 * keys[a].*field + h10 * h * tangent(keys, a, field) + h01 * keys[a + 1].*field +
         h11 * h * tangent(keys, a + 1, field);
}

}  // namespace

CameraKey CameraPath::at(float time) const {
  CameraKey out = time <= keys.front().time ? keys.front() : keys.back();
  out.time = time;
  if (keys.size() < 2 || time <= keys.front().time || time >= keys.back().time) return out;
  auto next = std::upper_bound(keys.begin(), keys.end(), time,
                               [](float t, const CameraKey& k) { return t < k.time; });
  size_t a = size_t(next - keys.begin()) - 1;
  float h = keys[a + 1].time - keys[a].time;
  float u = (time - keys[a].time) / h;
  out.position = hermite(keys, a, u, h, &CameraKey::position);
  out.target = hermite(keys, a, u, h, &CameraKey::target);
  return out;
}

}  // namespace mirage
