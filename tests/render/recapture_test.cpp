// The re-capture rule (render/recapture.h) on the CPU: which captures a frame redoes, and the
// angle a motion subtends, against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "render/recapture.h"

namespace mirage {
namespace {

Drift turned(float degrees, int age = 0) {
  Drift d;
  d.angle = glm::radians(degrees);
  d.age = age;
  return d;
}

TEST(ChooseRecaptures, InvalidFirstThenMostDriftedWithinTheBudget) {
  Drift invalid;
  invalid.invalid = true;
  Drift unmeasured;
  unmeasured.unmeasured = true;
  const std::vector<Drift> drift = {turned(0.5f), turned(3.0f), invalid, turned(2.0f),
                                    unmeasured,   turned(5.0f), invalid};
  const RecapturePolicy policy{1.0f, 0.0f, 2};
  // Invalid ones whatever the budget; then the unmeasured change and the 5° turn; the 3° and 2°
  // turns wait; the 0.5° one is within the tolerance.
  EXPECT_EQ(chooseRecaptures(drift, policy), (std::vector<int>{2, 6, 4, 5}));
  EXPECT_EQ(chooseRecaptures(drift, {1.0f, 0.0f, 0}), (std::vector<int>{2, 6, 4, 5, 1, 3}));
}

TEST(ChooseRecaptures, ZeroTolerancesRecaptureAnyChangeAndNothingElse) {
  Drift moved;
  moved.texels = 1e-4f;
  const std::vector<Drift> drift = {turned(0.0f), turned(1e-3f), moved, Drift{}};
  EXPECT_EQ(chooseRecaptures(drift, {}), (std::vector<int>{1, 2}));
}

TEST(ChooseRecaptures, TexelsAreATolerance) {
  Drift small, large;
  small.texels = 1.5f;
  large.texels = 2.5f;
  EXPECT_EQ(chooseRecaptures({small, large}, {90.0f, 2.0f, 0}), (std::vector<int>{1}));
}

TEST(ChooseRecaptures, EqualDriftsGoOldestFirst) {
  const std::vector<Drift> drift = {turned(4.0f, 1), turned(4.0f, 7), turned(4.0f, 3)};
  EXPECT_EQ(chooseRecaptures(drift, {1.0f, 0.0f, 2}), (std::vector<int>{1, 2}));
}

const Bounds3 kUnitBox{vec3(-0.5f), vec3(0.5f)};

TEST(MotionAngle, ATranslationSubtendsItsLengthOverTheDistance) {
  const mat4 before(1.0f), now = glm::translate(mat4(1.0f), vec3(0.1f, 0.0f, 0.0f));
  const vec3 viewer(0.0f, 0.0f, 5.0f);
  // The box now spans z in [-0.5, 0.5]: its nearest face is 4.5 from the viewer.
  const float angle = motionAngle(kUnitBox, before, now, viewer, viewer, kUnitBox.transformed(now));
  EXPECT_NEAR(angle, std::atan2(0.1f, 4.5f), 1e-6f);
  // A viewer that moves with the object sees nothing move.
  const vec3 carried = viewer + vec3(0.1f, 0.0f, 0.0f);
  EXPECT_EQ(motionAngle(kUnitBox, before, now, viewer, carried, kUnitBox.transformed(now)), 0.0f);
}

TEST(MotionAngle, AViewerInsideTheBoxMeasuresToItsNearestFace) {
  const Bounds3 room{vec3(-2.0f), vec3(2.0f)};
  const vec3 before_eye(0.0f), now_eye(0.0f, 0.3f, 0.0f);
  // The room stands still; the viewer rose 0.3 and is 1.7 below the ceiling.
  EXPECT_NEAR(motionAngle(room, mat4(1.0f), mat4(1.0f), before_eye, now_eye, room),
              std::atan2(0.3f, 1.7f), 1e-6f);
}

TEST(MotionAngle, ATurnMovesTheFarthestCorner) {
  const mat4 now = glm::rotate(mat4(1.0f), glm::radians(90.0f), vec3(0, 1, 0));
  const vec3 viewer(0.0f, 0.0f, 10.0f);
  // A corner (0.5, y, 0.5) goes to (0.5, y, -0.5): 1 unit; the nearest face stays 9.5 away.
  EXPECT_NEAR(motionAngle(kUnitBox, mat4(1.0f), now, viewer, viewer, kUnitBox.transformed(now)),
              std::atan2(1.0f, 9.5f), 1e-5f);
}

}  // namespace
}  // namespace mirage
