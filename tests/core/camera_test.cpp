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

// A view mirrored in a plane shows at pixel (x, y) what the view sees at (x, y) in the mirror:
// a point in front of the mirror projects where its mirror image projects in the original view;
// its view matrix has determinant -1; the mirror plane is its near plane (points behind the
// mirror fall before it, in front after it); and the primary rays are the reflected ones.
TEST(View, MirroredViewSeesThroughTheMirror) {
  CameraDesc c;
  c.position = {1.0f, 1.5f, 4.0f};
  c.target = {-0.5f, 1.0f, 0.0f};
  const View v(c, {320, 240});
  const vec3 point(0.2f, 1.0f, -1.0f), normal = glm::normalize(vec3(0.1f, 0.0f, 1.0f));
  const View m = v.mirrored(point, normal);
  auto reflect = [&](vec3 x) { return x - 2.0f * glm::dot(x - point, normal) * normal; };
  EXPECT_LT(glm::length(m.eye() - reflect(v.eye())), 1e-5f);
  EXPECT_NEAR(glm::determinant(mat3(m.viewMatrix())), -1.0f, 1e-5f);
  for (vec3 q : {vec3(0.0f, 1.2f, 0.5f), vec3(-0.8f, 0.6f, 2.0f), vec3(0.5f, 1.4f, -0.5f)}) {
    ASSERT_GT(glm::dot(q - point, normal), 0.0f);
    const vec3 in_mirror = m.project(q), in_view = v.project(reflect(q));
    EXPECT_NEAR(in_mirror.x, in_view.x, 1e-3f);
    EXPECT_NEAR(in_mirror.y, in_view.y, 1e-3f);
    const vec4 clip = m.viewProjection() * vec4(q, 1.0f);
    EXPECT_GT(clip.z / clip.w, -1.0f);  // after the near plane: drawn
    EXPECT_LT(clip.z / clip.w, 1.0f);
  }
  const vec3 behind = point - 0.3f * normal + vec3(0.1f, 0.1f, 0.0f);
  const vec4 clip = m.viewProjection() * vec4(behind, 1.0f);
  EXPECT_LT(clip.z / clip.w, -1.0f);  // before the near plane: clipped
  const Ray ray = v.primaryRay(100.0f, 80.0f), mirrored_ray = m.primaryRay(100.0f, 80.0f);
  EXPECT_LT(glm::length(mirrored_ray.direction - glm::reflect(ray.direction, normal)), 1e-5f);
  // An eye behind the mirror has no mirrored view.
  EXPECT_THROW(v.mirrored(point, -normal), Error);
}

}  // namespace
}  // namespace mirage
