// A glTF file's cameras and KHR_lights_punctual light against the values its node transforms give
// by hand (gltf_scene_files.h), and the checks on their numbers.
#include <gtest/gtest.h>

#include "scene/gltf_scene_files.h"
#include "scene/log_capture.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"

namespace mirage {
namespace {

using nlohmann::json;
using test::cameraScene;
using test::ExpectedCamera;
using test::expectInputError;
using test::LogCapture;
using test::QuadScene;
using test::TempDir;
using test::writeGltf;

constexpr float kTolerance = 1e-5f;

void expectNear(vec3 got, vec3 want, const char* what) {
  EXPECT_NEAR(glm::distance(got, want), 0.0f, kTolerance)
      << what << ": (" << got.x << ", " << got.y << ", " << got.z << ") want (" << want.x << ", "
      << want.y << ", " << want.z << ")";
}

void expectCamera(const CameraDesc& c, const ExpectedCamera& want) {
  SCOPED_TRACE(c.name);
  expectNear(c.position, want.position, "position");
  expectNear(glm::normalize(c.target - c.position), want.forward, "forward");
  EXPECT_NEAR(glm::distance(c.target, c.position), 1.0f, kTolerance);
  expectNear(c.up, want.up, "up");
  EXPECT_NEAR(c.fov_y_degrees, want.fov_y_degrees, kTolerance);
  EXPECT_NEAR(c.near_plane, want.near_plane, kTolerance);
  EXPECT_NEAR(c.far_plane, want.far_plane, kTolerance);
  EXPECT_NEAR(c.aspect, want.aspect, kTolerance);
}

TEST(GltfSceneParts, CamerasAndLightFollowTheNodeTransforms) {
  TempDir dir;
  QuadScene s = cameraScene();
  const std::string path = writeGltf(dir, s, "scene.gltf");
  LogCapture log;
  const LoadedModel m = loadModel(path);

  EXPECT_EQ(m.mesh_node, (std::vector<std::string>{"mirror", "red_box"}));
  EXPECT_TRUE(m.materials[size_t(m.mesh_material[0])].isReflector());
  ASSERT_EQ(m.cameras.size(), 2u);  // the orthographic camera is skipped
  // Depth-first in file order: rig's child cam_a_node before the root cam_b.
  EXPECT_EQ(m.cameras[0].name, "cam_a");  // the camera's own name, not its node's
  EXPECT_EQ(m.cameras[1].name, "cam_b");  // an unnamed camera: its node's name
  expectCamera(m.cameras[0], test::expectedCamA());
  expectCamera(m.cameras[1], test::expectedCamB());

  ASSERT_TRUE(m.light.has_value());
  expectNear(m.light->direction, test::expectedSunDirection(), "light direction");
  expectNear(m.light->color, test::kSunColor, "light colour");
  EXPECT_EQ(m.light->ambient, Light().ambient);

  EXPECT_EQ(log.count({"warning", path, "camera 'top'", "orthographic", "skipped"}), 1u);
  EXPECT_EQ(log.count({"warning", path, "light 'bulb'", "point", "ignored"}), 1u);
}

TEST(GltfSceneParts, FurtherDirectionalLightsAndRepeatedNamesAreWarnedAbout) {
  TempDir dir;
  QuadScene s = cameraScene();
  s.doc["extensions"]["KHR_lights_punctual"]["lights"][1] = {{"type", "directional"}};
  s.doc["cameras"][1]["name"] = "cam_a";
  LogCapture log;
  const LoadedModel m = loadModel(writeGltf(dir, s, "twice.gltf"));
  ASSERT_EQ(m.cameras.size(), 2u);
  EXPECT_EQ(m.cameras[0].name, "cam_a");
  EXPECT_EQ(m.cameras[1].name, "cam_a-2");
  EXPECT_EQ(log.count({"warning", "twice.gltf", "'cam_a' is called 'cam_a-2'"}), 1u);
  // The first directional light in node order (sun_node comes before bulb_node) is kept.
  expectNear(m.light->color, test::kSunColor, "light colour");
  EXPECT_EQ(log.count({"warning", "lights[1]", "second directional light", "ignored"}), 1u);
}

TEST(GltfSceneParts, FileWithoutCamerasOrLightsHasNone) {
  TempDir dir;
  QuadScene s = test::quadScene(dir);
  const LoadedModel m = loadModel(writeGltf(dir, s));
  EXPECT_TRUE(m.cameras.empty());
  EXPECT_FALSE(m.light.has_value());
  EXPECT_EQ(m.mesh_node, (std::vector<std::string>{"child", "instance", "tex"}));
}

TEST(GltfSceneParts, FarPlaneOfAnInfiniteCameraReachesPastTheScene) {
  TempDir dir;
  QuadScene s = cameraScene();
  // cam_b 5000 units away: twice the distance to the farthest corner of the scene's bounds.
  s.doc["nodes"][3]["translation"] = {0, 0, 5000};
  s.doc["nodes"][3].erase("rotation");
  const LoadedModel m = loadModel(writeGltf(dir, s, "far.gltf"));
  ASSERT_EQ(m.cameras[1].name, "cam_b");
  // Bounds x [-2, 2], y [0, 4], z [-2, 0.5]: the farthest corner is (+-2, 4, -2).
  EXPECT_NEAR(m.cameras[1].far_plane, 2.0f * glm::length(vec3(2, 4, 5002)), 1e-2f);
}

struct BadCamera {
  const char* label;
  json perspective;
  const char* field;  // what the message names
};

TEST(GltfSceneParts, BadCameraNumbersNameTheFileCameraAndField) {
  const BadCamera cases[] = {
      {"yfov of pi", {{"yfov", 3.2}, {"znear", 0.1}}, "perspective.yfov = 3.2"},
      {"yfov of 0", {{"yfov", 0}, {"znear", 0.1}}, "perspective.yfov = 0"},
      {"negative znear", {{"yfov", 0.5}, {"znear", -1}}, "perspective.znear = -1"},
      {"zfar before znear", {{"yfov", 0.5}, {"znear", 2}, {"zfar", 1}}, "perspective.zfar = 1"},
      {"negative aspect",
       {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", -2}},
       "perspective.aspectRatio = -2"},
  };
  TempDir dir;
  for (const BadCamera& c : cases) {
    SCOPED_TRACE(c.label);
    QuadScene s = cameraScene();
    s.doc["cameras"][0]["perspective"] = c.perspective;
    const std::string path = writeGltf(dir, s, "bad.gltf");
    expectInputError([&] { loadModel(path); }, {path, "camera 'cam_a'", c.field, "allowed range"});
  }
}

TEST(GltfSceneParts, BadReferencesAndTransformsAreInputErrors) {
  TempDir dir;
  QuadScene s = cameraScene();
  s.doc["nodes"][3]["camera"] = 7;
  std::string path = writeGltf(dir, s, "ref.gltf");
  expectInputError([&] { loadModel(path); }, {path, "node 3 refers to camera 7"});

  s = cameraScene();
  s.doc["nodes"][6]["extensions"]["KHR_lights_punctual"]["light"] = 9;
  path = writeGltf(dir, s, "light.gltf");
  expectInputError([&] { loadModel(path); }, {path, "node 6", "light = 9 is outside 0..1"});

  s = cameraScene();
  s.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -1;
  path = writeGltf(dir, s, "dark.gltf");
  expectInputError([&] { loadModel(path); }, {path, "light 'sun'", "intensity = -1"});

  // A scale of 0 on cam_a's parent collapses its view direction.
  s = cameraScene();
  s.doc["nodes"][2]["scale"] = {0, 0, 0};
  path = writeGltf(dir, s, "flat.gltf");
  expectInputError([&] { loadModel(path); }, {path, "camera 'cam_a'", "view direction"});
}

}  // namespace
}  // namespace mirage
