#include <gtest/gtest.h>

#include "core/camera.h"
#include "core/error.h"

namespace mirage {
namespace {

CameraDesc testCamera() {
  CameraDesc c;
  c.position = {1.0f, 2.0f, 5.0f};
  c.target = {0.0f, 0.5f, 0.0f};
  c.fov_y_degrees = 50.0f;
  return c;
}

TEST(View, CentreRayLooksAtTheTarget) {
  View view(testCamera(), {640, 480});
  Ray r = view.primaryRay(320.0f, 240.0f);
  vec3 expected = glm::normalize(vec3(0.0f, 0.5f, 0.0f) - vec3(1.0f, 2.0f, 5.0f));
  EXPECT_NEAR(glm::dot(r.direction, expected), 1.0f, 1e-6f);
}

TEST(View, ProjectInvertsPrimaryRays) {
  View view(testCamera(), {300, 200});
  for (vec2 p :
       {vec2(0.5f, 0.5f), vec2(299.5f, 10.5f), vec2(150.0f, 199.5f), vec2(42.25f, 77.75f)}) {
    Ray r = view.primaryRay(p.x, p.y);
    vec3 q = view.project(r.at(7.0f));
    EXPECT_NEAR(q.x, p.x, 1e-3f);
    EXPECT_NEAR(q.y, p.y, 1e-3f);
  }
}

TEST(View, RowZeroIsTheTop) {
  View view(testCamera(), {100, 100});
  EXPECT_GT(glm::dot(view.primaryRay(50, 0).direction, view.up()), 0.0f);
  EXPECT_LT(glm::dot(view.primaryRay(50, 100).direction, view.up()), 0.0f);
  EXPECT_GT(glm::dot(view.primaryRay(100, 50).direction, view.right()), 0.0f);
}

TEST(View, RejectsDegenerateCameras) {
  CameraDesc c = testCamera();
  c.target = c.position;
  EXPECT_THROW(View(c, {10, 10}), InputError);
  EXPECT_THROW(View(testCamera(), {0, 10}), InputError);
}

}  // namespace
}  // namespace mirage
