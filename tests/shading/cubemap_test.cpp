// Cube-map addressing (shading/cubemap.h) against the OpenGL specification's table.
#include <gtest/gtest.h>

#include "shading/cubemap.h"

namespace mirage {
namespace {

using shading::cube_direction;
using shading::cube_face_st;

TEST(CubeMap, AxesSelectTheirFacesAtTheCentre) {
  const vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    vec2 st;
    EXPECT_EQ(cube_face_st(axes[f], st), f);
    EXPECT_NEAR(st.x, 0.5f, 1e-6f);
    EXPECT_NEAR(st.y, 0.5f, 1e-6f);
  }
}

TEST(CubeMap, MatchesTheSpecificationTable) {
  // GL 4.5 table 8.19: +X face: sc = -rz, tc = -ry. A direction towards +X, slightly +Y and +Z
  // lands left (s < 0.5) and up (t < 0.5) on the face.
  vec2 st;
  EXPECT_EQ(cube_face_st(vec3(1.0f, 0.2f, 0.4f), st), 0);
  EXPECT_NEAR(st.x, 0.5f * (-0.4f + 1.0f), 1e-6f);
  EXPECT_NEAR(st.y, 0.5f * (-0.2f + 1.0f), 1e-6f);
  // +Y face: sc = rx, tc = rz.
  EXPECT_EQ(cube_face_st(vec3(0.3f, 1.0f, -0.6f), st), 2);
  EXPECT_NEAR(st.x, 0.5f * (0.3f + 1.0f), 1e-6f);
  EXPECT_NEAR(st.y, 0.5f * (-0.6f + 1.0f), 1e-6f);
  // -Z face: sc = -rx, tc = -ry.
  EXPECT_EQ(cube_face_st(vec3(0.5f, -0.25f, -1.0f), st), 5);
  EXPECT_NEAR(st.x, 0.5f * (-0.5f + 1.0f), 1e-6f);
  EXPECT_NEAR(st.y, 0.5f * (0.25f + 1.0f), 1e-6f);
}

TEST(CubeMap, DirectionIsTheInverseOfFaceSt) {
  for (int f = 0; f < 6; ++f)
    for (float s : {0.05f, 0.3f, 0.5f, 0.77f, 0.95f})
      for (float t : {0.02f, 0.4f, 0.5f, 0.66f, 0.98f}) {
        vec2 st;
        int face = cube_face_st(cube_direction(f, vec2(s, t)), st);
        EXPECT_EQ(face, f);
        EXPECT_NEAR(st.x, s, 1e-5f);
        EXPECT_NEAR(st.y, t, 1e-5f);
      }
}

}  // namespace
}  // namespace mirage
