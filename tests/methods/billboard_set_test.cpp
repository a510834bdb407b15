// Billboard placement (the impostor paper, §3): planar objects are their own billboards, other
// objects get one per reflector through their centre, perpendicular to the line to the
// reflector, and reflectors get one per other reflector; the capture camera frames the quad.
#include <gtest/gtest.h>

#include <algorithm>

#include "methods/impostor/billboard_set.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

vec3 quadCentre(const BillboardSpec& b) {
  return b.corner + 0.5f * (b.edge_u + b.edge_v);
}
vec3 quadNormal(const BillboardSpec& b) {
  return glm::normalize(glm::cross(b.edge_u, b.edge_v));
}

TEST(BillboardSet, PlanarDetection) {
  Scene scene = spheresOverFloor();
  vec3 n;
  EXPECT_TRUE(isPlanarInstance(scene, instanceNamed(scene, "floor"), mat4(1.0f), &n));
  EXPECT_NEAR(std::abs(n.y), 1.0f, 1e-6f);
  EXPECT_FALSE(isPlanarInstance(scene, instanceNamed(scene, "box"), mat4(1.0f)));
  EXPECT_FALSE(isPlanarInstance(scene, instanceNamed(scene, "sphere-a"), mat4(1.0f)));
}

TEST(BillboardSet, CountsAndRanges) {
  Scene scene = spheresOverFloor();
  BillboardSet set = placeBillboards(scene, 0.0f, {});
  // 1 planar (floor), 1 object x 2 reflectors, 2 x 1 reflective.
  ASSERT_EQ(set.billboards.size(), 5u);
  EXPECT_EQ(set.surface_layers, 5);
  EXPECT_EQ(set.position_layers, 2);
  EXPECT_TRUE(set.unbillboarded.empty());
  ASSERT_EQ(set.ranges.size(), 2u);
  const std::vector<int> reflectors = scene.reflectorInstances();
  for (int r = 0; r < 2; ++r) {
    ivec4 range = set.ranges[size_t(r)].range;
    EXPECT_EQ(range.y, 2) << "D = the floor + the box's billboard for this reflector";
    EXPECT_EQ(range.w, 1) << "R - 1 reflective billboards";
    EXPECT_EQ(range.z, range.x + range.y)
        << "the reflective entries follow the diffuse ones (the shader tests both in one loop)";
    for (int k = range.x; k < range.x + range.y; ++k) {
      const BillboardSpec& b = set.billboards[size_t(set.entries[size_t(k)])];
      EXPECT_NE(b.kind, BillboardSpec::Kind::kReflective);
      if (b.kind == BillboardSpec::Kind::kObject) {
        EXPECT_EQ(b.reflector, r);
      }
    }
    const BillboardSpec& rb = set.billboards[size_t(set.entries[size_t(range.z)])];
    EXPECT_EQ(rb.kind, BillboardSpec::Kind::kReflective);
    EXPECT_NE(rb.represents, r) << "a ray never tests the billboard of the reflector it leaves";
    EXPECT_EQ(rb.object, reflectors[size_t(rb.represents)]);
  }
  // Planar only: the box goes to the environment instead.
  BillboardSetOptions planar;
  planar.objects = false;
  BillboardSet only = placeBillboards(scene, 0.0f, planar);
  EXPECT_EQ(only.surface_layers, 3);
  EXPECT_EQ(only.position_layers, 2);
  ASSERT_EQ(only.unbillboarded.size(), 1u);
  EXPECT_EQ(only.unbillboarded[0], instanceNamed(scene, "box"));
}

// A planar reflector keeps a list per side of its plane, each without the billboards wholly on
// the other side; a curved reflector keeps one list, every billboard in it.
TEST(BillboardSet, APlanarReflectorsListsHoldWhatLiesOnTheirSide) {
  const Scene scene = mirrorWallBetweenObjects();
  const BillboardSet set = placeBillboards(scene, 0.0f, {});
  const std::vector<int> reflectors = scene.reflectorInstances();
  ASSERT_EQ(reflectors.size(), 2u);
  auto names = [&](const ivec4& range, const BillboardSet& in) {
    std::vector<std::string> out;
    for (int k = range.x; k < range.x + range.y + range.w; ++k) {
      const int billboard = in.entries[size_t(k)];
      out.push_back(scene.instances[size_t(in.billboards[size_t(billboard)].object)].name);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  using Names = std::vector<std::string>;
  const int wall = reflectors[0] == instanceNamed(scene, "wall") ? 0 : 1;
  const shading::BillboardRange& lists = set.ranges[size_t(wall)];
  ASSERT_NEAR(std::abs(lists.plane.z), 1.0f, 1e-6f);  // the plane z = 0
  EXPECT_NEAR(lists.plane.w, 0.0f, 1e-6f);
  const bool faces_front = lists.plane.z > 0.0f;
  const Names front = {"ball-front", "box-front", "floor", "sphere"};
  const Names back = {"ball-back", "box-back", "floor"};
  EXPECT_EQ(names(lists.range, set), faces_front ? front : back);
  EXPECT_EQ(names(lists.back, set), faces_front ? back : front);
  EXPECT_EQ(shading::billboard_list(lists, vec3(0.0f, 0.3f, 1.0f)),
            faces_front ? lists.range : lists.back);
  // The sphere's one list: every object and the wall.
  const shading::BillboardRange& sphere = set.ranges[size_t(1 - wall)];
  EXPECT_EQ(sphere.plane, vec4(0.0f));
  EXPECT_EQ(sphere.back, sphere.range);
  EXPECT_EQ(names(sphere.range, set),
            (Names{"ball-back", "ball-front", "box-back", "box-front", "floor", "wall"}));
  // Off: one list for the wall too.
  BillboardSetOptions one;
  one.sides = false;
  const BillboardSet all = placeBillboards(scene, 0.0f, one);
  EXPECT_EQ(all.ranges[size_t(wall)].back, all.ranges[size_t(wall)].range);
  EXPECT_EQ(names(all.ranges[size_t(wall)].range, all),
            (Names{"ball-back", "ball-front", "box-back", "box-front", "floor", "sphere"}));
}

TEST(BillboardSet, PlanarBillboardLiesInTheObjectsPlaneAndCoversIt) {
  Scene scene = spheresOverFloor();
  BillboardSet set = placeBillboards(scene, 0.0f, {});
  const BillboardSpec& floor = set.billboards[0];
  ASSERT_EQ(floor.kind, BillboardSpec::Kind::kPlanar);
  EXPECT_NEAR(floor.corner.y, 0.0f, 1e-5f);
  EXPECT_NEAR(floor.edge_u.y, 0.0f, 1e-5f);
  EXPECT_NEAR(floor.edge_v.y, 0.0f, 1e-5f);
  // The 8 x 8 floor fits: its corners have quad coordinates in [0, 1].
  for (vec3 c : {vec3(-4, 0, -4), vec3(4, 0, -4), vec3(-4, 0, 4), vec3(4, 0, 4)}) {
    vec3 local = c - floor.corner;
    float u = glm::dot(local, floor.edge_u) / glm::dot(floor.edge_u, floor.edge_u);
    float v = glm::dot(local, floor.edge_v) / glm::dot(floor.edge_v, floor.edge_v);
    EXPECT_GE(u, -1e-5f);
    EXPECT_LE(u, 1.0f + 1e-5f);
    EXPECT_GE(v, -1e-5f);
    EXPECT_LE(v, 1.0f + 1e-5f);
  }
  // Captured from above, where the reflectors are.
  EXPECT_GT(floor.camera.position.y, 0.0f);
}

TEST(BillboardSet, ObjectBillboardsFaceTheirReflector) {
  Scene scene = spheresOverFloor();
  BillboardSet set = placeBillboards(scene, 0.0f, {});
  const std::vector<int> reflectors = scene.reflectorInstances();
  int seen = 0;
  for (const BillboardSpec& b : set.billboards) {
    if (b.kind == BillboardSpec::Kind::kPlanar) continue;
    const Bounds3 object = scene.instanceBounds(b.object);
    const vec3 viewer = scene.instanceBounds(reflectors[size_t(b.reflector)]).center();
    // Through the object's centre, perpendicular to the line to the reflector's centre.
    const vec3 c = quadCentre(b);
    EXPECT_NEAR(glm::length(c - object.center()), 0.0f, 1e-4f);
    const vec3 to_viewer = glm::normalize(viewer - object.center());
    EXPECT_NEAR(std::abs(glm::dot(quadNormal(b), to_viewer)), 1.0f, 1e-5f);
    // The camera stands on that line, on the reflector's side, and the quad holds the
    // bounding sphere's cross-section.
    EXPECT_GT(glm::dot(b.camera.position - object.center(), to_viewer), 0.0f);
    EXPECT_NEAR(glm::length(glm::cross(b.camera.position - object.center(), to_viewer)), 0.0f,
                1e-3f);
    EXPECT_GE(0.5f * glm::length(b.edge_u), object.radius() * 0.999f);
    EXPECT_NEAR(glm::dot(b.edge_u, b.edge_v), 0.0f, 1e-4f);
    if (b.object == instanceNamed(scene, "box")) ++seen;
  }
  EXPECT_EQ(seen, 2);
}

TEST(BillboardSet, CaptureCameraMapsTexelsOntoTheQuad) {
  // Texel (s, t) of the captured image (t from the bottom row, GL's order) must show the quad
  // point corner + s * edge_u + t * edge_v: View::project gives top-left pixel coordinates.
  Scene scene = spheresOverFloor();
  BillboardSet set = placeBillboards(scene, 0.0f, {});
  const int n = 256;
  for (const BillboardSpec& b : set.billboards) {
    View view(b.camera, {n, n});
    for (vec2 uv : {vec2(0.25f, 0.25f), vec2(0.9f, 0.1f), vec2(0.1f, 0.8f), vec2(0.5f)}) {
      vec3 px = view.project(b.corner + uv.x * b.edge_u + uv.y * b.edge_v);
      EXPECT_NEAR(px.x / float(n), uv.x, 1e-3f);
      EXPECT_NEAR(1.0f - px.y / float(n), uv.y, 1e-3f);
    }
  }
}

}  // namespace
}  // namespace mirage::test
