// Axis-aligned bounding box.
#pragma once

#include <algorithm>

#include "core/math.h"

namespace mirage {

struct Bounds3 {
  vec3 lo{kInfinity};
  vec3 hi{-kInfinity};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void extend(const vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend(const Bounds3& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  vec3 center() const { return 0.5f * (lo + hi); }
  vec3 extent() const { return hi - lo; }
  float radius() const { return 0.5f * glm::length(hi - lo); }
  bool contains(const vec3& p) const {
    return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
  }
  // The bounds of this box's eight corners under an affine transform.
  Bounds3 transformed(const mat4& m) const {
    Bounds3 out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
      vec3 c((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
      out.extend(transformPoint(m, c));
    }
    return out;
  }
};

}  // namespace mirage
