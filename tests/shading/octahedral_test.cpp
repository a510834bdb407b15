// The octahedral map of shading/octahedral.h against its definition: every unit vector lands on
// the square [-1, 1]^2 with |x| + |y| <= 1 for the upper half, and comes back to itself. The
// shaders run this very code (method `ssr`'s G-buffer normals).
#include <gtest/gtest.h>

#include <cmath>

#include "shading/octahedral.h"

namespace mirage {
namespace {

using shading::octahedral_decode;
using shading::octahedral_encode;

// n points spread over the sphere (a Fibonacci lattice).
std::vector<vec3> sphereDirections(int n) {
  std::vector<vec3> out;
  const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < n; ++i) {
    const float z = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
    const float r = std::sqrt(std::max(1.0f - z * z, 0.0f));
    out.push_back(vec3(r * std::cos(golden * float(i)), r * std::sin(golden * float(i)), z));
  }
  return out;
}

TEST(Octahedral, AxesGoToTheSquaresCentreAndCorners) {
  EXPECT_EQ(octahedral_encode(vec3(0, 0, 1)), vec2(0, 0));
  EXPECT_EQ(octahedral_encode(vec3(1, 0, 0)), vec2(1, 0));
  EXPECT_EQ(octahedral_encode(vec3(0, -1, 0)), vec2(0, -1));
  // The lower pole folds onto a corner (on the axis planes the sign is taken as +).
  EXPECT_EQ(octahedral_encode(vec3(0, 0, -1)), vec2(1, 1));
  EXPECT_EQ(octahedral_decode(vec2(1, 1)), vec3(0, 0, -1));
  EXPECT_EQ(octahedral_decode(vec2(-1, 1)), vec3(0, 0, -1));
}

TEST(Octahedral, UpperHalfInsideTheDiamondLowerHalfOutside) {
  for (const vec3& n : sphereDirections(2000)) {
    const vec2 e = octahedral_encode(n);
    ASSERT_LE(std::abs(e.x), 1.0f + 1e-6f);
    ASSERT_LE(std::abs(e.y), 1.0f + 1e-6f);
    if (n.z > 1e-3f) {
      EXPECT_LT(std::abs(e.x) + std::abs(e.y), 1.0f) << n.x << " " << n.y;
    }
    if (n.z < -1e-3f) {
      EXPECT_GT(std::abs(e.x) + std::abs(e.y), 1.0f) << n.x << " " << n.y;
    }
  }
}

TEST(Octahedral, RoundTripKeepsTheDirection) {
  float worst = 0.0f;
  for (const vec3& n : sphereDirections(20000)) {
    const vec3 back = octahedral_decode(octahedral_encode(n));
    worst = std::max(worst, glm::length(back - n));
    // Not unit vectors in: the map takes directions.
    const vec3 scaled = octahedral_decode(octahedral_encode(3.5f * n));
    worst = std::max(worst, glm::length(scaled - n));
  }
  // Float rounding only (the G-buffer holds the two numbers as full floats).
  EXPECT_LT(worst, 1e-6f);
}

}  // namespace
}  // namespace mirage
