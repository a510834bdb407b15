// The probe blend weights of shading/probe_blend.h, the very code the blended probe lookup runs:
// analytic values, and no step anywhere along a walk across two overlapping probes.
#include <gtest/gtest.h>

#include <algorithm>

#include "shading/probe_blend.h"

namespace mirage::shading {
namespace {

TEST(ProbeBlend, ABoxWeighsZeroOnItsFacesAndOneAtTheBlendDistanceInside) {
  const vec3 lo(-1.0f, 0.0f, -2.0f), hi(1.0f, 3.0f, 2.0f);
  EXPECT_FLOAT_EQ(probe_box_weight({1.0f, 1.5f, 0.0f}, lo, hi, 0.5f), 0.0f);
  EXPECT_FLOAT_EQ(probe_box_weight({0.75f, 1.5f, 0.0f}, lo, hi, 0.5f), 0.5f);
  EXPECT_FLOAT_EQ(probe_box_weight({0.5f, 1.5f, 0.0f}, lo, hi, 0.5f), 1.0f);
  EXPECT_FLOAT_EQ(probe_box_weight({0.0f, 1.5f, 0.0f}, lo, hi, 0.5f), 1.0f);
  // The nearest face decides: 0.1 above the floor.
  EXPECT_FLOAT_EQ(probe_box_weight({0.0f, 0.1f, 0.0f}, lo, hi, 0.5f), 0.2f);
  EXPECT_FLOAT_EQ(probe_box_weight({1.5f, 1.5f, 0.0f}, lo, hi, 0.5f), 0.0f);
  // No blend distance: a step at the faces.
  EXPECT_FLOAT_EQ(probe_box_weight({0.99f, 1.5f, 0.0f}, lo, hi, 0.0f), 1.0f);
  EXPECT_FLOAT_EQ(probe_box_weight({1.01f, 1.5f, 0.0f}, lo, hi, 0.0f), 0.0f);
}

TEST(ProbeBlend, ASphereWeighsByTheDistanceInsideItsSurface) {
  const vec3 c(1.0f, 2.0f, 3.0f);
  EXPECT_FLOAT_EQ(probe_sphere_weight(c + vec3(2.0f, 0.0f, 0.0f), c, 2.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(probe_sphere_weight(c + vec3(0.0f, 1.5f, 0.0f), c, 2.0f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(probe_sphere_weight(c, c, 2.0f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(probe_sphere_weight(c + vec3(0.0f, 0.0f, 3.0f), c, 2.0f, 1.0f), 0.0f);
}

TEST(ProbeBlend, AProbeTakesWhatThoseBeforeItLeft) {
  EXPECT_FLOAT_EQ(probe_blend_share(1.0f, 0.0f), 1.0f);
  EXPECT_FLOAT_EQ(probe_blend_share(1.0f, 0.3f), 0.7f);
  EXPECT_FLOAT_EQ(probe_blend_share(0.2f, 0.3f), 0.2f);
  EXPECT_FLOAT_EQ(probe_blend_share(0.5f, 1.0f), 0.0f);
}

// Two box probes overlapping along x (the first, smaller, is taken first) and a radiance for each
// and for the environment: the blended radiance along a fine walk from one end to the other moves
// by at most (the radiance's spread) x (step / blend distance) between steps: no step anywhere,
// while without a blend distance it jumps at the first probe's face.
float blendedAt(float x, float blend) {
  const vec3 p(x, 1.5f, 0.0f);
  const float west = 0.2f, east = 0.9f, sky = 5.0f;
  const float w1 = probe_box_weight(p, {-8.0f, -1.0f, -4.0f}, {1.0f, 4.0f, 4.0f}, blend);
  const float s1 = probe_blend_share(w1, 0.0f);
  const float w2 = probe_box_weight(p, {-1.0f, -1.0f, -4.0f}, {9.0f, 4.0f, 4.0f}, blend);
  const float s2 = probe_blend_share(w2, s1);
  return s1 * west + s2 * east + std::max(1.0f - s1 - s2, 0.0f) * sky;
}

TEST(ProbeBlend, AWalkAcrossTwoOverlappingProbesHasNoStep) {
  const float step = 1e-3f, blend = 1.0f;
  // The largest change per unit walked: the spread of the radiances (0.7 between the probes) over
  // the blend distance.
  float steepest = 0.0f;
  for (int i = 0; i < 15000; ++i) {
    const float x0 = -7.0f + float(i) * step, x1 = -7.0f + float(i + 1) * step;
    steepest = std::max(steepest, std::abs(blendedAt(x1, blend) - blendedAt(x0, blend)) / (x1 - x0));
  }
  EXPECT_LE(steepest, 0.7f / blend * 1.01f);
  // Everywhere on the walk the probes take it all: the sky takes nothing.
  for (float x = -7.0f; x < 8.0f; x += 0.25f) {
    const float v = blendedAt(x, blend);
    EXPECT_GE(v, 0.2f - 1e-5f);
    EXPECT_LE(v, 0.9f + 1e-5f);
  }
  // The same probes without a blend distance: one step of the whole spread at x = 1.
  EXPECT_NEAR(blendedAt(1.0f + step, 0.0f) - blendedAt(1.0f - step, 0.0f), 0.7f, 1e-5f);
}

}  // namespace
}  // namespace mirage::shading
