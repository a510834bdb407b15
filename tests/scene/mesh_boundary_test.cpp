// boundaryEdgeFraction: closed generated surfaces (seams and poles welded) are closed, open
// ones are open by exactly their rim.
#include <gtest/gtest.h>

#include "scene/mesh.h"
#include "scene/procedural.h"

namespace mirage {
namespace {

TEST(MeshBoundary, ClosedSurfacesHaveNoBoundaryAfterWelding) {
  for (int segments : {24, 96, 500}) {
    EXPECT_EQ(boundaryEdgeFraction(procedural::sphere(1.0f, segments, segments / 2)), 0.0);
    EXPECT_EQ(boundaryEdgeFraction(procedural::cylinder(0.5f, 1.0f, segments)), 0.0);
    EXPECT_EQ(boundaryEdgeFraction(procedural::torus(1.0f, 0.25f, segments, segments / 4)), 0.0);
  }
  EXPECT_EQ(boundaryEdgeFraction(procedural::box(vec3(1.0f))), 0.0);
}

TEST(MeshBoundary, OpenSurfacesCountTheirRim) {
  // A quad: two triangles, five edges, the four sides open.
  EXPECT_DOUBLE_EQ(boundaryEdgeFraction(procedural::quad(1.0f, 1.0f)), 0.8);
  // A dish (a lathe from the rim to the axis): its rim of 10 edges is open.
  const Mesh dish = procedural::lathe({{1.0f, 1.0f}, {0.5f, 0.2f}, {0.0f, 0.0f}}, 10);
  const double fraction = boundaryEdgeFraction(dish);
  EXPECT_GT(fraction, 0.0);
  // One triangle alone: all three edges.
  Mesh one;
  one.positions = {vec3(0.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f)};
  one.triangles = {uvec3(0, 1, 2)};
  EXPECT_DOUBLE_EQ(boundaryEdgeFraction(one), 1.0);
  EXPECT_EQ(boundaryEdgeFraction(Mesh{}), 0.0);
}

}  // namespace
}  // namespace mirage
