// A camera path: keyframes of the eye and the point it looks at, for a walk through a scene that
// `mirage compare --path-frames` measures frame by frame (a recorded camera path, as the papers
// measure quality along a walk rather than at one chosen view).
#pragma once

#include <vector>

#include "core/math.h"

namespace mirage {

struct CameraKey {
  float time = 0.0f;  // seconds; strictly increasing along a path
  vec3 position{0.0f};
  vec3 target{0.0f};
};

// Position and target each follow a cubic Hermite spline through the keys with Catmull-Rom
// tangents for unevenly spaced times, (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]), one-sided at the two
// ends: the path passes through every key with continuous velocity (a walk, not a polyline with
// kinks), and two keys give a straight line at constant speed. Before the first key the first
// holds, after the last the last.
struct CameraPath {
  std::vector<CameraKey> keys;  // sorted by time; at least two when not empty (validated)

  bool empty() const { return keys.empty(); }
  float start() const { return keys.empty() ? 0.0f : keys.front().time; }
  float end() const { return keys.empty() ? 0.0f : keys.back().time; }
  float duration() const { return end() - start(); }
  // The interpolated key at `time` (its `time` is `time`); needs a non-empty path.
  CameraKey at(float time) const;
};

}  // namespace mirage
