// A ray: origin, direction (not necessarily unit) and the parametric interval it covers.
#pragma once

#include "core/math.h"

namespace mirage {

struct Ray {
  vec3 origin{0.0f};
  vec3 direction{0.0f, 0.0f, -1.0f};
  float tmin = 0.0f;
  float tmax = kInfinity;

  vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace mirage
