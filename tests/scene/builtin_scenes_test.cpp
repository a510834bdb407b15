// Built-in scenes: every mesh of every one has unit normals (lathes with the axis at both ends
// included); and `glass` (the hybrid paper's goblet-shaped mirror): one valid goblet of a moderate
// triangle count standing on the floor, its bowl's inside facing up (concave), a straw through
// its rim, the other objects clear of it, and the bowl large in camera "main"; the walks of the
// planar-mirror scenes.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/camera.h"
#include "scene/builtin_scenes.h"

namespace mirage::test {
namespace {

int instanceNamed(const Scene& s, const std::string& name) {
  for (size_t i = 0; i < s.instances.size(); ++i)
    if (s.instances[i].name == name) return int(i);
  ADD_FAILURE() << "no instance " << name;
  return 0;
}

TEST(BuiltinScenes, EveryMeshHasUnitNormals) {
  for (const BuiltinSceneInfo& info : builtinScenes()) {
    Scene s = makeBuiltinScene(info.name);
    for (const Mesh& m : s.meshes) {
      ASSERT_EQ(m.normals.size(), m.vertexCount()) << info.name << "/" << m.name;
      size_t bad = 0;
      for (const vec3& n : m.normals) bad += !(std::abs(glm::length(n) - 1.0f) < 1e-4f);
      EXPECT_EQ(bad, 0u) << info.name << "/" << m.name;
    }
  }
}

TEST(BuiltinGlass, GobletIsOneValidMirrorOfModerateSize) {
  Scene s = makeBuiltinScene("glass");
  ASSERT_EQ(s.reflectorInstances().size(), 1u);
  int goblet = s.reflectorInstances()[0];
  EXPECT_EQ(s.instances[size_t(goblet)].name, "goblet");
  const Mesh& m = s.meshes[size_t(s.instances[size_t(goblet)].mesh)];
  EXPECT_NO_THROW(m.validate());
  EXPECT_GE(m.triangleCount(), 2000u);
  EXPECT_LE(m.triangleCount(), 6000u);
  Bounds3 b = s.instanceBounds(goblet);
  EXPECT_NEAR(b.lo.y, 0.0f, 1e-5f);  // on the floor
  EXPECT_NEAR(b.hi.y, 1.2f, 0.05f);  // about 1.2 tall
  EXPECT_GT(b.extent().x, 0.8f);

  // The lowest vertex on the axis above the foot is the bowl's inner bottom: its normal points
  // up, into the bowl (a concave mirror); below it, the stem's top, the bowl's outside faces down.
  const float r_max = 1e-4f;
  float inner_bottom = 1e9f;
  size_t inner_index = 0;
  for (size_t i = 0; i < m.vertexCount(); ++i) {
    vec3 p = m.positions[i];
    if (std::hypot(p.x, p.z) < r_max && p.y > 0.3f && p.y < inner_bottom) {
      inner_bottom = p.y;
      inner_index = i;
    }
  }
  ASSERT_LT(inner_bottom, 1.0f);
  EXPECT_GT(m.normals[inner_index].y, 0.99f);
  // Outer bowl vertices (radius 0.3, below the rim, outside the inner wall) face outwards.
  int outer = 0;
  for (size_t i = 0; i < m.vertexCount(); ++i) {
    vec3 p = m.positions[i];
    float r = std::hypot(p.x, p.z);
    if (p.y > inner_bottom + 0.02f && p.y < 1.1f && r > 0.25f) {
      vec3 radial = vec3(p.x, 0.0f, p.z) / r;
      // Either the outer surface (normal away from the axis) or the inner one (towards it).
      EXPECT_GT(std::abs(glm::dot(m.normals[i], radial)), 0.2f) << i;
      outer += glm::dot(m.normals[i], radial) > 0.0f;
    }
  }
  EXPECT_GT(outer, 0);
}

TEST(BuiltinGlass, StrawGoesThroughTheRimAndTheOthersStayClear) {
  Scene s = makeBuiltinScene("glass");
  int goblet = instanceNamed(s, "goblet");
  Bounds3 gb = s.instanceBounds(goblet);
  // The rim: the outer wall ends 0.008 below the top, at the largest radius.
  const float rim_y = gb.hi.y - 0.008f, rim_r = 0.5f * gb.extent().x;

  // The straw's axis crosses the rim height within the bowl's wall, inside the bowl below it.
  int straw = instanceNamed(s, "straw");
  EXPECT_FALSE(s.isReflector(straw));
  mat4 m = s.instances[size_t(straw)].matrixAt(0.0f);
  Bounds3 local = s.meshes[size_t(s.instances[size_t(straw)].mesh)].bounds();
  vec3 base = transformPoint(m, vec3(0.0f)), tip = transformPoint(m, vec3(0, local.hi.y, 0));
  ASSERT_GT(tip.y, rim_y);
  ASSERT_LT(base.y, rim_y);
  vec3 at_rim = glm::mix(base, tip, (rim_y - base.y) / (tip.y - base.y));
  float r = std::hypot(at_rim.x, at_rim.z);
  EXPECT_GT(r, rim_r - 0.03f);
  EXPECT_LT(r, rim_r + 0.01f);
  EXPECT_LT(std::hypot(base.x, base.z), 0.3f);  // it stands in the bowl
  EXPECT_GT(tip.y, gb.hi.y + 0.2f);             // and sticks out

  // 3-4 coloured objects besides the floor and the straw, none touching the goblet.
  int others = 0;
  for (size_t i = 0; i < s.instances.size(); ++i) {
    const std::string& name = s.instances[i].name;
    if (int(i) == goblet || name == "straw" || name == "floor") continue;
    ++others;
    EXPECT_FALSE(s.isReflector(int(i))) << name;
    Bounds3 b = s.instanceBounds(int(i));
    bool overlap = b.lo.x < gb.hi.x && b.hi.x > gb.lo.x && b.lo.z < gb.hi.z && b.hi.z > gb.lo.z &&
                   b.lo.y < gb.hi.y;
    EXPECT_FALSE(overlap) << name << " touches the goblet";
    EXPECT_NEAR(b.lo.y, 0.0f, 1e-4f) << name << " stands on the floor";
  }
  EXPECT_GE(others, 3);
  EXPECT_LE(others, 4);
}

TEST(BuiltinGlass, MainCameraLooksDownIntoALargeBowl) {
  Scene s = makeBuiltinScene("glass");
  View view(s.camera("main"), {720, 512});
  Bounds3 gb = s.instanceBounds(instanceNamed(s, "goblet"));
  const float rim_y = gb.hi.y, r = 0.5f * gb.extent().x;
  EXPECT_GT(view.eye().y, rim_y + 0.3f);  // above the rim, looking down
  float lo_x = 1e9f, hi_x = -1e9f, lo_y = 1e9f, hi_y = -1e9f;
  for (int k = 0; k < 32; ++k) {
    float phi = 2.0f * kPi * float(k) / 32.0f;
    vec3 p = view.project({r * std::cos(phi), rim_y, r * std::sin(phi)});
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  // The whole rim in the frame, at least 40 % of its width, seen open (an ellipse, not a line).
  EXPECT_GE(lo_x, 0.0f);
  EXPECT_LE(hi_x, 720.0f);
  EXPECT_GE(lo_y, 0.0f);
  EXPECT_LE(hi_y, 512.0f);
  EXPECT_GT(hi_x - lo_x, 0.4f * 720.0f);
  EXPECT_GT(hi_y - lo_y, 0.3f * (hi_x - lo_x));
}

// The "walk" cameras of mirror-room and two-mirrors: about six seconds, the eye in front of every
// planar mirror at every moment and the mirror it looks at in view, so that every frame of
// `compare --path-frames` measures reflections.
TEST(BuiltinScenes, WalksStayInFrontOfTheMirrorAndKeepItInView) {
  for (const char* name : {"mirror-room", "two-mirrors"}) {
    Scene s = makeBuiltinScene(name);
    const CameraDesc& walk = s.camera("walk");
    ASSERT_GE(walk.path.keys.size(), 2u) << name;
    EXPECT_NEAR(walk.path.duration(), 6.0f, 1.0f) << name;
    std::vector<int> mirrors = planarReflectors(s);
    ASSERT_FALSE(mirrors.empty()) << name;
    const ivec2 size(720, 512);
    float travelled = 0.0f;
    vec3 previous = walk.at(walk.path.start()).position;
    for (int k = 0; k <= 60; ++k) {
      const float t = walk.path.start() + walk.path.duration() * float(k) / 60.0f;
      View view(walk.at(t), size);
      travelled += glm::distance(view.eye(), previous);
      previous = view.eye();
      int in_view = 0;
      for (int i : mirrors) {
        const mat4 model = s.instances[size_t(i)].matrixAt(t);
        vec3 normal;
        ASSERT_TRUE(isPlanarInstance(s, i, model, &normal));
        const Bounds3 local = s.meshes[size_t(s.instances[size_t(i)].mesh)].bounds();
        const vec3 centre = transformPoint(model, local.center());
        // The mirror's front: its normal faces into the room (towards the scene's centre).
        const vec3 front = glm::dot(normal, s.bounds().center() - centre) > 0.0f ? normal : -normal;
        EXPECT_GT(glm::dot(front, view.eye() - centre), 0.3f) << name << " at t = " << t;
        vec3 p = view.project(centre);
        in_view += p.z > 0.0f && p.x > 0.05f * float(size.x) && p.x < 0.95f * float(size.x) &&
                   p.y > 0.05f * float(size.y) && p.y < 0.95f * float(size.y);
      }
      EXPECT_GE(in_view, 1) << name << " at t = " << t;
    }
    EXPECT_GT(travelled, 3.0f) << name << ": a walk across the room";
  }
}

}  // namespace
}  // namespace mirage::test
