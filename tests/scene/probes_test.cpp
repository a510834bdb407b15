// A scene file's "probes" (scene/probes.h, scene_json_probes.cpp): what is read, the blend order,
// what each probe shows, and the errors and warnings on bad probes.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/probes.h"
#include "scene/scene_json.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

// A floor, a box and two mirror balls (at x = -3 and x = 3), with `probes` as the file's probes.
std::string probeScene(const std::string& probes) {
  return R"({"materials": [{"name": "grey", "type": "diffuse"}, {"name": "chrome", "type": "reflector"}],
    "meshes": [{"name": "floor", "procedural": "quad", "size": [20, 20]},
               {"name": "box", "procedural": "box", "size": [1, 1, 1]},
               {"name": "ball", "procedural": "sphere", "radius": 0.5}],
    "instances": [{"name": "floor", "mesh": "floor", "material": "grey"},
                  {"name": "box", "mesh": "box", "material": "grey", "translate": [0, 0.5, 0]},
                  {"name": "west-ball", "mesh": "ball", "material": "chrome", "translate": [-3, 1, 0]},
                  {"name": "east-ball", "mesh": "ball", "material": "chrome", "translate": [3, 1, 0]}],
    "probes": )" +
         probes + "}";
}

Scene loadText(const std::string& text) {
  const std::filesystem::path file = testTempDir("scene-probes") / "probes.json";
  writeText(file, text);
  return loadSceneJson(file.string());
}

std::string errorOf(const std::string& probes) {
  try {
    loadText(probeScene(probes));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kTwoProbes = R"([
    {"name": "west", "position": [-3, 1, 2], "influence": {"box": {"min": [-10, -1, -10], "max": [1, 5, 10]}},
     "blend_distance": 1, "proxy": {"box": {"min": [-10, 0, -10], "max": [10, 5, 10]}}},
    {"position": [3, 1, 2], "influence": {"sphere": 4}, "priority": 2}])";

TEST(SceneProbes, AreReadWithTheirVolumesProxiesAndDefaults) {
  const Scene scene = loadText(probeScene(kTwoProbes));
  ASSERT_EQ(scene.probes.size(), 2u);
  const ReflectionProbe& west = scene.probes[0];
  EXPECT_EQ(west.name, "west");
  EXPECT_EQ(west.position, vec3(-3.0f, 1.0f, 2.0f));
  EXPECT_FALSE(west.influence.sphere);
  EXPECT_EQ(west.influence.box.hi, vec3(1.0f, 5.0f, 10.0f));
  EXPECT_FLOAT_EQ(west.blend_distance, 1.0f);
  EXPECT_EQ(west.proxy.box.lo, vec3(-10.0f, 0.0f, -10.0f));
  EXPECT_EQ(west.priority, 0);
  const ReflectionProbe& east = scene.probes[1];
  EXPECT_EQ(east.name, "probe-2");
  EXPECT_TRUE(east.influence.sphere);
  EXPECT_EQ(east.influence.centre, east.position);
  EXPECT_FLOAT_EQ(east.influence.radius, 4.0f);
  // No proxy given: the influence volume is the proxy.
  EXPECT_TRUE(east.proxy.sphere);
  EXPECT_FLOAT_EQ(east.proxy.radius, 4.0f);
  EXPECT_EQ(east.priority, 2);
  EXPECT_FLOAT_EQ(east.blend_distance, 0.0f);
}

TEST(SceneProbes, BlendInPriorityOrderThenTheSmallerVolumeFirst) {
  Scene scene = loadText(probeScene(kTwoProbes));
  EXPECT_EQ(probeBlendOrder(scene.probes), (std::vector<int>{1, 0}));
  scene.probes[1].priority = 0;  // the sphere (268) is smaller than the box (11 x 6 x 20)
  EXPECT_EQ(probeBlendOrder(scene.probes), (std::vector<int>{1, 0}));
  scene.probes[1].influence.radius = 20.0f;
  EXPECT_EQ(probeBlendOrder(scene.probes), (std::vector<int>{0, 1}));
}

TEST(SceneProbes, InfluenceTheReflectorsTheirVolumesMeetAndShowAllButTheOneTheyAreIn) {
  Scene scene = loadText(probeScene(kTwoProbes));
  const int west_ball = 2, east_ball = 3;
  EXPECT_EQ(reflectorsInfluenced(scene, scene.probes[0]), (std::vector<int>{west_ball}));
  EXPECT_EQ(reflectorsInfluenced(scene, scene.probes[1]), (std::vector<int>{east_ball}));
  const auto at_rest = [&](int i) { return scene.instanceBounds(i); };
  EXPECT_EQ(shownByReflectionProbe(scene, scene.probes[0], at_rest),
            (std::vector<int>{0, 1, 2, 3}));
  scene.probes[0].position = vec3(-3.0f, 1.0f, 0.0f);  // inside the west ball
  EXPECT_EQ(shownByReflectionProbe(scene, scene.probes[0], at_rest), (std::vector<int>{0, 1, 3}));
  // The bounds at the capture's time decide: the ball moved away shows again.
  const auto moved = [&](int i) {
    const Bounds3 b = scene.instanceBounds(i);
    return i == west_ball ? Bounds3{b.lo + vec3(0, 10, 0), b.hi + vec3(0, 10, 0)} : b;
  };
  EXPECT_EQ(shownByReflectionProbe(scene, scene.probes[0], moved), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(probeWarnings(scene).empty());
}

TEST(SceneProbes, WarnOfAProbeThatInfluencesNothingAndAReflectorThatNoProbeDoes) {
  const Scene scene = loadText(probeScene(
      R"([{"name": "lost", "position": [0, 30, 0], "influence": {"sphere": 2}},
          {"name": "west", "position": [-3, 1, 2], "influence": {"sphere": 3}}])"));
  const std::vector<std::string> warnings = probeWarnings(scene);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("probes[0] ('lost') influences no reflector"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("reflector 'east-ball' is in no probe's influence volume"),
            std::string::npos)
      << warnings[1];
}

TEST(SceneProbes, BadProbesAreErrorsNamingTheFieldAndTheAllowedValues) {
  struct Case {
    const char* probes;   // the scene file's "probes"
    const char* message;  // what its error says
  };
  const Case cases[] = {
      {R"([{"position": [0, 1, 0], "influence": {"sphere": 2}, "blend_distance": 3}])",
       "probes[0].blend_distance = 3 is outside the allowed range [0, 2]"},
      {R"([{"position": [0, 1, 0],
            "influence": {"box": {"min": [0, 0, 0], "max": [1, 0, 1]}}}])",
       "probes[0].influence.box.max = [1, 0, 1]: must exceed min"},
      {R"([{"position": [5, 1, 0],
            "influence": {"box": {"min": [-1, 0, -1], "max": [1, 2, 1]}}}])",
       "probes[0].influence does not hold the probe's position [5, 1, 0]"},
      {R"([{"position": [0, 1, 0], "influence": {"sphere": 9},
            "proxy": {"box": {"min": [1, 0, 0], "max": [2, 2, 2]}}}])",
       "probes[0].proxy does not hold the probe's position [0, 1, 0]"},
      {R"([{"position": [5, 1, 0], "influence": {"sphere": 9}, "proxy": {"sphere": 1},
            "priority": 1.5}])",
       "probes[0].priority"},
      {R"([{"position": [0, 1, 0], "influence": {"sphere": 2, "box": {"size": [1, 1, 1]}}}])",
       "probes[0].influence needs exactly one of \"box\" and \"sphere\""},
      {R"([{"position": [0, 1, 0], "influence": {"sphere": 2}, "size": 3}])", "probes[0]"},
      {R"([{"name": "a", "position": [0, 1, 0], "influence": {"sphere": 2}},
           {"name": "a", "position": [0, 1, 0], "influence": {"sphere": 2}}])",
       "probes[1].name = 'a' is already the name of another probe"},
      {R"({"position": [0, 1, 0]})", "probes must be an array"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.probes);
    EXPECT_NE(errorOf(c.probes).find(c.message), std::string::npos);
  }
}

}  // namespace
}  // namespace mirage::test
