// The reflector G-buffer's host-side rules: the screen rectangle a reflector's screen-space draw
// is scissored to, and the choice between that draw and a pass over the reflector's triangles.
#include "render/reflector_gbuffer.h"

#include <gtest/gtest.h>

namespace mirage {
namespace {

// An eye 5 units in front of the origin looking at it, 90 degrees vertically, 200x200 pixels:
// at distance d a unit is 100 / d pixels from the centre.
View frontView() {
  CameraDesc camera;
  camera.position = vec3(0.0f, 0.0f, 5.0f);
  camera.target = vec3(0.0f);
  camera.fov_y_degrees = 90.0f;
  return View(camera, ivec2(200, 200));
}

TEST(ScreenRectangle, ABoxProjectsToItsPixelsWidenedToWholeQuads) {
  // The near face at distance 4.9 spans 100 +- 100 / 4.9 = [79.59, 120.41]: a pixel of margin,
  // then out to even coordinates.
  const Bounds3 box{vec3(-1.0f, -1.0f, -0.1f), vec3(1.0f, 1.0f, 0.1f)};
  EXPECT_EQ(screenRectangle(box, frontView()), ivec4(78, 78, 122, 122));
}

TEST(ScreenRectangle, ClampedToTheViewAndEmptyOffIt) {
  const View view = frontView();
  // Reaching past the right edge: clamped to the view's width.
  const ivec4 right = screenRectangle({vec3(4.0f, -1.0f, 0.0f), vec3(6.0f, 1.0f, 0.0f)}, view);
  EXPECT_EQ(right.z, 200);
  EXPECT_LT(right.x, right.z);
  // Wholly right of it: empty.
  const ivec4 off = screenRectangle({vec3(8.0f, -1.0f, 0.0f), vec3(9.0f, 1.0f, 0.0f)}, view);
  EXPECT_GE(off.x, off.z);
  // An empty box: nothing.
  const ivec4 none = screenRectangle(Bounds3{}, view);
  EXPECT_GE(none.x, none.z);
}

TEST(ScreenRectangle, ABoxReachingBehindTheEyeIsTheWholeView) {
  const ivec4 r = screenRectangle({vec3(-1.0f, -1.0f, 0.0f), vec3(1.0f, 1.0f, 6.0f)}, frontView());
  EXPECT_EQ(r, ivec4(0, 0, 200, 200));
}

TEST(ScreenPassPays, WhereTheTrianglesCoverFewPixelsOfTheRectangleEach) {
  const ivec4 rect(0, 0, 100, 100);  // 10,000 pixels
  EXPECT_TRUE(screenPassPays(size_t(10000 / kScreenPassPixelsPerTriangle), rect));
  EXPECT_FALSE(screenPassPays(size_t(10000 / kScreenPassPixelsPerTriangle) - 1, rect));
  EXPECT_FALSE(screenPassPays(0, rect));
  EXPECT_TRUE(screenPassPays(1, ivec4(10, 10, 10, 20)));  // an empty rectangle: nothing to pay
}

}  // namespace
}  // namespace mirage
