// Dynamic scenes on the CPU: the ripple against its closed form (heights, the height-field
// normal, the gradient by finite differences), moving lights (slerp at a constant angular
// speed, held ends, loops), the bounds that hold every shape, and the motions of the built-in
// scenes (still at time 0, moving after).
#include <cmath>

#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "scene/deformation.h"
#include "scene/procedural.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

Deformation someRipple() {
  Deformation d;
  d.kind = Deformation::Kind::kRipple;
  d.amplitude = 0.05f;
  d.wavelength = 0.7f;
  d.speed = 0.3f;
  d.decay = 2.0f;
  d.center = vec3(0.4f, 0.0f, -0.3f);
  return d;
}

TEST(Ripple, HeightsFollowTheClosedForm) {
  const Deformation d = someRipple();
  const Mesh rest = procedural::quad(3.0f, 2.0f, 1.0f, 30, 20);
  Mesh out;
  const float t = 1.3f;
  deformMesh(rest, d, t, out);
  ASSERT_EQ(out.positions.size(), rest.positions.size());
  EXPECT_EQ(out.triangles, rest.triangles);
  const float k = 2.0f * kPi / d.wavelength, soft = 0.25f * d.wavelength;
  float largest = 0.0f;
  for (size_t i = 0; i < rest.positions.size(); ++i) {
    const vec3 p = rest.positions[i];
    const float r = std::sqrt(glm::dot(p - d.center, p - d.center) + soft * soft);
    const float h = d.amplitude * std::exp(-r / d.decay) * std::sin(k * (r - d.speed * t));
    EXPECT_NEAR(out.positions[i].y, h, 1e-6f);
    EXPECT_FLOAT_EQ(out.positions[i].x, p.x);
    EXPECT_FLOAT_EQ(out.positions[i].z, p.z);
    largest = std::max(largest, std::abs(h));
  }
  EXPECT_GT(largest, 0.5f * d.amplitude);  // the test sees real waves
}

TEST(Ripple, NormalsAreTheHeightFieldsAndTheGradientIsTheDerivative) {
  const Deformation d = someRipple();
  const Mesh rest = procedural::quad(3.0f, 2.0f, 1.0f, 24, 16);
  Mesh out;
  deformMesh(rest, d, 0.6f, out);
  const float e = 1e-3f;
  for (size_t i = 0; i < rest.positions.size(); ++i) {
    const vec3 p = rest.positions[i];
    // Central differences of h over x and z.
    const float hx =
        (d.height(p + vec3(e, 0, 0), 0.6f) - d.height(p - vec3(e, 0, 0), 0.6f)) / (2 * e);
    const float hz =
        (d.height(p + vec3(0, 0, e), 0.6f) - d.height(p - vec3(0, 0, e), 0.6f)) / (2 * e);
    const vec3 g = d.gradient(p, 0.6f);
    EXPECT_NEAR(g.x, hx, 2e-3f);
    EXPECT_NEAR(g.z, hz, 2e-3f);
    // A height field y = h(x, z) has the normal (-h_x, 1, -h_z), normalised.
    const vec3 expected = glm::normalize(vec3(-hx, 1.0f, -hz));
    EXPECT_GT(glm::dot(out.normals[i], expected), 1.0f - 1e-5f) << i;
  }
}

TEST(Ripple, TravelsOutwardsAndRepeatsAfterItsPeriod) {
  const Deformation d = someRipple();
  const vec3 p(1.5f, 0.0f, 0.4f);
  EXPECT_FLOAT_EQ(d.period(), d.wavelength / d.speed);
  EXPECT_NEAR(d.height(p, 0.2f), d.height(p, 0.2f + d.period()), 1e-5f);
  EXPECT_GT(std::abs(d.height(p, 0.2f) - d.height(p, 0.2f + 0.25f * d.period())), 1e-3f);
  // A crest moves outwards: the phase at (r + v dt, t + dt) equals the phase at (r, t); with the
  // fall-off off, so are the heights (away from the softened source).
  Deformation flat = d;
  flat.decay = 0.0f;
  const vec3 dir = glm::normalize(p - d.center);
  const float dt = 0.4f;
  EXPECT_NEAR(flat.height(p, 1.0f), flat.height(p + dir * (d.speed * dt), 1.0f + dt), 2e-3f);
  Deformation still = d;
  still.amplitude = 0.0f;
  EXPECT_FALSE(still.active());
  EXPECT_EQ(still.period(), 0.0f);
}

TEST(Ripple, ScenesBoundsHoldEveryShapeAndDeformingMirrorsAreNotPlanar) {
  const Scene s = makeBuiltinScene("ripple-pool");
  const int pool = instanceNamed(s, "pool");
  ASSERT_GE(pool, 0);
  ASSERT_TRUE(s.instances[size_t(pool)].deforms());
  EXPECT_FALSE(isPlanarInstance(s, pool, s.instances[size_t(pool)].matrixAt(0.0f)));
  EXPECT_GT(s.duration(), 0.0f);
  for (float t : {0.0f, 0.4f, 1.1f, 2.3f}) {
    Mesh m;
    s.meshAt(pool, t, m);
    const Bounds3 b = s.instanceBounds(pool, t);
    const mat4 model = s.instances[size_t(pool)].matrixAt(t);
    for (const vec3& p : m.positions) EXPECT_TRUE(b.contains(transformPoint(model, p)));
  }
}

TEST(MovingLight, TurnsAtAConstantSpeedHoldsItsEndsAndLoops) {
  Light light;
  const vec3 a = glm::normalize(vec3(1, 1, 0)), b = glm::normalize(vec3(-1, 1, 0));  // 90° apart
  light.keys = {{1.0f, a, vec3(1, 0, 0)}, {3.0f, b, vec3(0, 0, 1)}};
  EXPECT_EQ(light.at(0.0f).direction, a);  // before the first key
  EXPECT_EQ(light.at(9.0f).direction, b);  // after the last
  for (float u : {0.25f, 0.5f, 0.75f}) {
    const Light l = light.at(1.0f + 2.0f * u);
    EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-5f);
    EXPECT_NEAR(std::acos(glm::dot(l.direction, a)), u * 0.5f * kPi, 1e-4f);
    EXPECT_NEAR(l.color.x, 1.0f - u, 1e-6f);
    EXPECT_NEAR(l.color.z, u, 1e-6f);
    EXPECT_TRUE(l.keys.empty());
  }
  light.loop = true;
  EXPECT_NEAR(glm::dot(light.at(2.0f).direction, light.at(4.0f).direction), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(light.at(1.5f).direction, light.at(5.5f).direction), 1.0f, 1e-5f);
}

TEST(BuiltinMotion, ScenesAreStillAtTimeZeroAndMoveAfter) {
  struct Case {
    const char* scene;
    std::vector<const char*> moving;
    bool light_moves;
  };
  const Case cases[] = {
      {"spheres9", {"mirror-sphere-1", "mirror-sphere-5", "mirror-sphere-9"}, false},
      {"mirror-room", {"teapot", "green-box"}, true},
  };
  for (const Case& c : cases) {
    const Scene s = makeBuiltinScene(c.scene);
    EXPECT_GT(s.duration(), 0.0f) << c.scene;
    for (const char* name : c.moving) {
      const Instance& inst = s.instances[size_t(instanceNamed(s, name))];
      ASSERT_FALSE(inst.animation.empty()) << c.scene << "/" << name;
      // Time 0 is the scene as it was before it moved: every still figure is unchanged.
      const mat4 rest = inst.transform.matrix(), at0 = inst.matrixAt(0.0f);
      for (int k = 0; k < 16; ++k) EXPECT_NEAR(at0[k / 4][k % 4], rest[k / 4][k % 4], 1e-5f);
      EXPECT_NE(inst.matrixAt(0.7f), at0) << c.scene << "/" << name;
      // Looping: one period on, it is back.
      const float period = inst.animation.duration();
      const mat4 again = inst.matrixAt(0.7f + period), now = inst.matrixAt(0.7f);
      for (int k = 0; k < 16; ++k) EXPECT_NEAR(again[k / 4][k % 4], now[k / 4][k % 4], 1e-4f);
    }
    const Light l0 = s.lightAt(0.0f), l1 = s.lightAt(1.3f);
    EXPECT_NEAR(glm::dot(l0.direction, s.light.direction), 1.0f, 1e-6f) << c.scene;
    EXPECT_EQ(glm::dot(l0.direction, l1.direction) < 0.999f, c.light_moves) << c.scene;
  }
  // The spheres bob above the floor, never into it.
  const Scene s = makeBuiltinScene("spheres9");
  for (int i : s.reflectorInstances())
    for (float t = 0.0f; t < 4.0f; t += 0.1f) EXPECT_GE(s.instanceBounds(i, t).lo.y, -1e-4f);
}

}  // namespace
}  // namespace mirage::test
