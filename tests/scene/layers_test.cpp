// The reflected scene's layers (scene/layers.h): planar parts of meshes against their known
// faces, and the default rule on the built-in scenes and on scenes made to sit on its edges.
#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "scene/layers.h"
#include "scene/procedural.h"
#include "scene/scene_json.h"
#include "support/scenes.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

// `b`'s triangles appended to `a` (one mesh of both).
Mesh merged(Mesh a, const Mesh& b) {
  const uint32_t base = uint32_t(a.positions.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  a.uvs.clear();
  for (const uvec3& t : b.triangles) a.triangles.push_back(t + uvec3(base));
  return a;
}

TEST(PlanarParts, AnInwardBoxIsSixFacesFacingIn) {
  const vec3 half(4.0f, 2.0f, 3.0f);
  float rest = -1.0f;
  const std::vector<PlanarPart> parts = planarParts(procedural::box(half, true), &rest);
  ASSERT_EQ(parts.size(), 6u);
  EXPECT_FLOAT_EQ(rest, 0.0f);
  float area = 0.0f;
  for (const PlanarPart& p : parts) {
    area += p.area;
    EXPECT_EQ(p.triangles, 2);
    // Each face's rectangle is the face: its centre on the box's surface, the normal towards
    // the box's centre, the rectangle's area the triangles' area.
    const vec3 centre = p.corner + 0.5f * (p.edge_u + p.edge_v);
    const int axis = std::abs(p.normal.x) > 0.5f ? 0 : (std::abs(p.normal.y) > 0.5f ? 1 : 2);
    EXPECT_NEAR(std::abs(centre[axis]), half[axis], 1e-5f);
    EXPECT_NEAR(p.normal[axis], centre[axis] > 0.0f ? -1.0f : 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::cross(p.edge_u, p.edge_v)), p.area, 1e-4f * p.area);
    EXPECT_NEAR(glm::dot(p.edge_u, p.normal), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(p.edge_v, p.normal), 0.0f, 1e-5f);
  }
  EXPECT_NEAR(area, 8.0f * (half.x * half.y + half.y * half.z + half.x * half.z), 1e-3f);
  // Largest first: the two 8 x 6 faces.
  EXPECT_NEAR(parts[0].area, 48.0f, 1e-3f);
  EXPECT_NEAR(parts[1].area, 48.0f, 1e-3f);
}

TEST(PlanarParts, ASphereHasNoneAndAQuadWithASphereHasOne) {
  const Mesh sphere = procedural::sphere(1.0f, 64, 32);
  float rest = 0.0f;
  EXPECT_TRUE(planarParts(sphere, &rest).empty());
  EXPECT_NEAR(rest, 4.0f * kPi, 0.05f);  // all of it, to the tessellation
  // A 10 x 10 floor and a unit sphere in one mesh: the floor is the one part, the sphere rest.
  const std::vector<PlanarPart> parts = planarParts(merged(procedural::quad(10.0f, 10.0f), sphere),
                                                    &rest);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_NEAR(parts[0].area, 100.0f, 1e-3f);
  EXPECT_NEAR(parts[0].normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(rest, 4.0f * kPi, 0.05f);
}

TEST(PlanarParts, PlanesApartByMoreThanTheToleranceStayApart) {
  // Two floors 1 mm apart in a mesh of size 10: 1e-4 of the size is 0.7 mm, so two parts.
  Mesh lower = procedural::quad(10.0f, 10.0f), upper = procedural::quad(10.0f, 10.0f);
  upper.transform(glm::translate(mat4(1.0f), vec3(0.0f, 1e-3f, 0.0f)));
  EXPECT_EQ(planarParts(merged(lower, upper)).size(), 2u);
  // 0.01 mm apart: one plane.
  upper.transform(glm::translate(mat4(1.0f), vec3(0.0f, -0.99e-3f, 0.0f)));
  EXPECT_EQ(planarParts(merged(lower, upper)).size(), 1u);
}

TEST(SceneLayers, TheRoomsAndTheFloorsAreEnvironment) {
  // A room holds its reflectors; a floor is many times their neighbourhood.
  for (const char* name : {"gallery", "mirror-room"}) {
    const Scene scene = makeBuiltinScene(name);
    const SceneLayers layers = sceneLayers(scene);
    const int room = instanceNamed(scene, "room");
    EXPECT_TRUE(layers.environment(room)) << name;
    EXPECT_EQ(layers.planesOf(room).size(), 6u) << name;
    EXPECT_TRUE(layers.rest.empty()) << name;  // a box is all planes
    EXPECT_EQ(layers.environmentInstances(), std::vector<int>{room}) << name;
    EXPECT_STREQ(layers.name(1), "reflector");  // the first mirror
  }
  const Scene checker = makeBuiltinScene("sphere-over-checker");
  const SceneLayers layers = sceneLayers(checker);
  EXPECT_TRUE(layers.environment(instanceNamed(checker, "floor")));
  EXPECT_EQ(layers.planesOf(instanceNamed(checker, "floor")).size(), 1u);
  EXPECT_FALSE(layers.environment(instanceNamed(checker, "red-box")));
  EXPECT_STREQ(layers.name(instanceNamed(checker, "red-box")), "object");
}

// A mirror ball of radius 1 at the origin and a diffuse box of half-size `half` at `at`.
Scene ballAndBox(const vec3& half, const vec3& at) {
  Scene s;
  addObject(s, "ball", procedural::sphere(1.0f, 16, 8), Material::mirror("chrome"),
            placeAt(vec3(0.0f)));
  addBox(s, "box", at, half, {0.5f, 0.5f, 0.5f}, 0.0f);
  finishScene(s, {0, 0, 10}, {0, 0, 0}, 40.0f);
  return s;
}

TEST(SceneLayers, TheRuleOnItsEdges) {
  // The neighbourhood is the ball's bounds, radius sqrt(3). A box beside it is an object up to
  // 4x that radius, environment beyond.
  const float neighbourhood = std::sqrt(3.0f);
  const float just_below = 0.99f * kEnvironmentSizeFactor * neighbourhood / std::sqrt(3.0f);
  const float just_above = 1.01f * kEnvironmentSizeFactor * neighbourhood / std::sqrt(3.0f);
  EXPECT_FALSE(sceneLayers(ballAndBox(vec3(just_below), {0, 0, -30})).environment(1));
  EXPECT_TRUE(sceneLayers(ballAndBox(vec3(just_above), {0, 0, -30})).environment(1));
  // A box holding the ball is environment whatever its size.
  EXPECT_TRUE(sceneLayers(ballAndBox(vec3(1.5f), vec3(0.0f))).environment(1));
  // One that only overlaps it is not.
  EXPECT_FALSE(sceneLayers(ballAndBox(vec3(1.5f), vec3(1.0f, 0.0f, 0.0f))).environment(1));
  // The scene file's choice wins either way.
  Scene chosen = ballAndBox(vec3(1.5f), vec3(0.0f));
  chosen.instances[1].layer = Layer::kObject;
  EXPECT_FALSE(sceneLayers(chosen).environment(1));
  EXPECT_EQ(sceneLayers(chosen).instances[1].why, "the scene file");
  chosen = ballAndBox(vec3(0.1f), {0, 0, -3});
  chosen.instances[1].layer = Layer::kEnvironment;
  EXPECT_TRUE(sceneLayers(chosen).environment(1));
  EXPECT_EQ(sceneLayers(chosen).planesOf(1).size(), 6u);
  // An animated instance is an object by default, even one holding the ball.
  Scene moving = ballAndBox(vec3(1.5f), vec3(0.0f));
  moving.instances[1].animation.keys.push_back({0.0f, moving.instances[1].transform});
  moving.instances[1].animation.keys.push_back({1.0f, moving.instances[1].transform});
  EXPECT_FALSE(sceneLayers(moving).environment(1));
  EXPECT_EQ(sceneLayers(moving).instances[1].why, "animated");
}

// A scene file of a floor, a box and a mirror ball, the box's instance entry ending with `extra`
// (JSON members), the ball's with `ball_extra`.
std::string layerScene(const std::string& extra, const std::string& ball_extra = "") {
  return R"({"materials": [{"name": "grey", "type": "diffuse"}, {"name": "chrome", "type": "reflector"}],
    "meshes": [{"name": "floor", "procedural": "quad", "size": [20, 20]},
               {"name": "box", "procedural": "box", "size": [1, 1, 1]},
               {"name": "ball", "procedural": "sphere", "radius": 0.5}],
    "instances": [{"name": "floor", "mesh": "floor", "material": "grey"},
                  {"name": "box", "mesh": "box", "material": "grey", "translate": [2, 0.5, 0])" +
         extra + R"(},
                  {"name": "ball", "mesh": "ball", "material": "chrome", "translate": [0, 1, 0])" +
         ball_extra + "}]}";
}

Scene loadText(const std::string& name, const std::string& text) {
  const std::filesystem::path file = testTempDir("scene-layers") / name;
  writeText(file, text);
  return loadSceneJson(file.string());
}

std::string errorOf(const std::string& name, const std::string& text) {
  try {
    loadText(name, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneLayers, AScenesFileSetsALayerAndBadLayersAreNamedErrors) {
  const Scene plain = loadText("plain.json", layerScene(""));
  EXPECT_FALSE(plain.instances[1].layer.has_value());
  EXPECT_TRUE(sceneLayers(plain).environment(0));  // the floor, 20 x 20 under a ball of 1
  EXPECT_FALSE(sceneLayers(plain).environment(1));
  const Scene chosen = loadText("chosen.json", layerScene(R"(, "layer": "environment")"));
  EXPECT_EQ(chosen.instances[1].layer, Layer::kEnvironment);
  EXPECT_TRUE(sceneLayers(chosen).environment(1));
  // Bad input: the file, the field, what is allowed.
  std::string e = errorOf("unknown.json", layerScene(R"(, "layer": "background")"));
  EXPECT_NE(e.find("unknown.json: instances[1].layer = 'background': unknown layer (allowed: "
                   "object, environment)"),
            std::string::npos)
      << e;
  e = errorOf("number.json", layerScene(R"(, "layer": 3)"));
  EXPECT_NE(e.find("number.json: instances[1].layer = 3: expected a string"), std::string::npos)
      << e;
  e = errorOf("reflector.json", layerScene("", R"(, "layer": "object")"));
  EXPECT_NE(e.find("reflector.json: instances[2].layer applies to diffuse instances only; "
                   "material 'chrome' is a reflector"),
            std::string::npos)
      << e;
}

}  // namespace
}  // namespace mirage::test
