// Camera paths: the spline passes through every key, holds the end keys outside the path's time
// span, is a straight line at constant speed with two keys, moves smoothly (no jumps, continuous
// velocity across keys), and CameraDesc::at takes position and target from it.
#include <gtest/gtest.h>

#include "core/camera.h"
#include "core/camera_path.h"

namespace mirage::test {
namespace {

CameraPath walk() {
  CameraPath p;
  p.keys = {{0.5f, {0, 1, 4}, {0, 1, 0}},
            {1.5f, {2, 1.2f, 3}, {-1, 1, 0}},
            {4.0f, {3, 1, 0}, {-2, 1, -1}},
            {6.0f, {1, 1.5f, -2}, {-2, 0.5f, -3}}};
  return p;
}

void expectNear(const vec3& a, const vec3& b, float tolerance) {
  EXPECT_LT(glm::distance(a, b), tolerance) << "(" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                            << b.x << ", " << b.y << ", " << b.z << ")";
}

TEST(CameraPath, PassesThroughEveryKey) {
  CameraPath p = walk();
  for (const CameraKey& k : p.keys) {
    CameraKey at = p.at(k.time);
    EXPECT_FLOAT_EQ(at.time, k.time);
    expectNear(at.position, k.position, 1e-5f);
    expectNear(at.target, k.target, 1e-5f);
  }
  EXPECT_FLOAT_EQ(p.start(), 0.5f);
  EXPECT_FLOAT_EQ(p.end(), 6.0f);
  EXPECT_FLOAT_EQ(p.duration(), 5.5f);
}

TEST(CameraPath, HoldsTheEndsOutsideItsSpan) {
  CameraPath p = walk();
  expectNear(p.at(0.0f).position, p.keys.front().position, 1e-6f);
  expectNear(p.at(-3.0f).target, p.keys.front().target, 1e-6f);
  expectNear(p.at(6.5f).position, p.keys.back().position, 1e-6f);
  expectNear(p.at(100.0f).target, p.keys.back().target, 1e-6f);
}

TEST(CameraPath, TwoKeysAreAStraightLineAtConstantSpeed) {
  CameraPath p;
  p.keys = {{1.0f, {0, 0, 0}, {0, 0, -1}}, {3.0f, {4, 2, 0}, {4, 2, -1}}};
  for (float u : {0.1f, 0.25f, 0.5f, 0.9f}) {
    CameraKey at = p.at(1.0f + 2.0f * u);
    expectNear(at.position, u * vec3(4, 2, 0), 1e-5f);
    expectNear(at.target, u * vec3(4, 2, 0) + vec3(0, 0, -1), 1e-5f);
  }
}

TEST(CameraPath, MovesSmoothlyThroughTheKeys) {
  CameraPath p = walk();
  // Small steps move the camera little (no jumps), and the velocity just before a key equals the
  // one just after it (Catmull-Rom tangents shared by the two segments).
  const float dt = 1e-3f;
  vec3 previous = p.at(p.start()).position;
  for (float t = p.start() + dt; t <= p.end(); t += dt) {
    vec3 now = p.at(t).position;
    EXPECT_LT(glm::distance(now, previous), 0.02f) << t;
    previous = now;
  }
  for (size_t i = 1; i + 1 < p.keys.size(); ++i) {
    const float t = p.keys[i].time, h = 1e-2f;
    vec3 before = (p.at(t).position - p.at(t - h).position) / h;
    vec3 after = (p.at(t + h).position - p.at(t).position) / h;
    // The central difference over the neighbours, as documented.
    vec3 tangent = (p.keys[i + 1].position - p.keys[i - 1].position) /
                   (p.keys[i + 1].time - p.keys[i - 1].time);
    expectNear(before, tangent, 0.05f);
    expectNear(after, tangent, 0.05f);
  }
}

TEST(CameraPath, CameraTakesPositionAndTargetFromItsPath) {
  CameraDesc still;
  still.position = {1, 2, 3};
  still.target = {0, 0, 0};
  CameraDesc same = still.at(2.0f);
  EXPECT_EQ(same.position, still.position);
  EXPECT_EQ(same.target, still.target);

  CameraDesc moving = still;
  moving.fov_y_degrees = 33.0f;
  moving.path = walk();
  CameraDesc at = moving.at(4.0f);
  EXPECT_EQ(at.position, moving.path.keys[2].position);
  EXPECT_EQ(at.target, moving.path.keys[2].target);
  EXPECT_FLOAT_EQ(at.fov_y_degrees, 33.0f);  // the camera's own
  View view(moving.at(5.0f), {64, 48});
  expectNear(view.eye(), moving.path.at(5.0f).position, 1e-6f);
}

}  // namespace
}  // namespace mirage::test
