// Model files as scenes: a file with a camera shown as it is (its nodes' placement, materials,
// cameras and light), the default stage for the others, and --stage deciding otherwise.
#include <gtest/gtest.h>

#include "scene/gltf_scene_files.h"
#include "scene/log_capture.h"
#include "scene/mesh_stage.h"
#include "scene/model_loader_files.h"
#include "scene/scene_loader.h"
#include "support/scenes.h"

namespace mirage {
namespace {

using test::instanceNamed;
using test::TempDir;

constexpr float kTolerance = 1e-5f;

SceneOptions stage(StageMode mode) {
  SceneOptions o;
  o.stage = mode;
  return o;
}

std::vector<std::string> cameraNames(const Scene& s) {
  std::vector<std::string> names;
  for (const CameraDesc& c : s.cameras) names.push_back(c.name);
  return names;
}

TEST(FileScene, FileWithCamerasIsShownAsItIs) {
  TempDir dir;
  test::QuadScene q = test::cameraScene();
  const std::string path = test::writeGltf(dir, q, "room.gltf");
  for (const Scene& s : {loadScene(path), loadScene(path, stage(StageMode::kAuto))}) {
    EXPECT_EQ(s.name, "room");
    EXPECT_EQ(instanceNamed(s, "floor"), -1);
    ASSERT_EQ(s.instances.size(), 2u);
    const int mirror = instanceNamed(s, "mirror"), box = instanceNamed(s, "red_box");
    ASSERT_GE(mirror, 0);
    ASSERT_GE(box, 0);
    EXPECT_EQ(s.reflectorInstances(), std::vector<int>{mirror});
    EXPECT_FALSE(s.isReflector(box));
    // Where the nodes put them, not fitted: the 2 x 2 quad scaled by 2 at (0, 2, -2).
    const Bounds3 b = s.instanceBounds(mirror);
    EXPECT_NEAR(glm::distance(b.lo, vec3(-2, 0, -2)), 0.0f, kTolerance);
    EXPECT_NEAR(glm::distance(b.hi, vec3(2, 4, -2)), 0.0f, kTolerance);
    EXPECT_EQ(cameraNames(s), (std::vector<std::string>{"cam_a", "cam_b"}));
    EXPECT_NEAR(glm::distance(s.cameras[0].position, test::expectedCamA().position), 0.0f,
                kTolerance);
    EXPECT_NEAR(glm::distance(s.light.direction, test::expectedSunDirection()), 0.0f, kTolerance);
    EXPECT_EQ(s.light.color, test::kSunColor);
    EXPECT_TRUE(s.environment.image.empty());  // the procedural sky
  }
}

TEST(FileScene, StageOnPutsTheFileOnTheDefaultStageWithItsCamerasFitted) {
  TempDir dir;
  test::QuadScene q = test::cameraScene();
  const std::string path = test::writeGltf(dir, q, "room.gltf");
  const Scene s = loadScene(path, stage(StageMode::kOn));
  EXPECT_GE(instanceNamed(s, "floor"), 0);
  EXPECT_EQ(cameraNames(s), (std::vector<std::string>{"main", "cam_a", "cam_b"}));
  // The file's bounds x [-2, 2], y [0, 4], z [-2, 0.5]: the fit scales by 2 / 4 about
  // (0, 0, -0.75) (centred in x and z, standing on y = 0).
  const test::ExpectedCamera want = test::expectedCamA();
  const CameraDesc& a = s.cameras[1];
  EXPECT_NEAR(glm::distance(a.position, 0.5f * (want.position - vec3(0, 0, -0.75f))), 0.0f,
              kTolerance);
  EXPECT_NEAR(glm::distance(glm::normalize(a.target - a.position), want.forward), 0.0f, kTolerance);
  EXPECT_NEAR(a.near_plane, 0.5f * want.near_plane, kTolerance);
  EXPECT_NEAR(a.far_plane, 0.5f * want.far_plane, kTolerance);
  EXPECT_EQ(a.aspect, want.aspect);
  EXPECT_EQ(s.light.color, Light().color);  // the stage's own light
}

TEST(FileScene, CameraLessFilesTakeTheStageUnlessStageOff) {
  TempDir dir;
  test::QuadScene q = test::quadScene(dir);
  const std::string path = test::writeGltf(dir, q);
  const Scene staged = loadScene(path);
  EXPECT_GE(instanceNamed(staged, "floor"), 0);
  EXPECT_EQ(cameraNames(staged), std::vector<std::string>{"main"});

  test::LogCapture log;
  const Scene off = loadScene(path, stage(StageMode::kOff));
  EXPECT_EQ(instanceNamed(off, "floor"), -1);
  EXPECT_EQ(cameraNames(off), std::vector<std::string>{"auto"});
  // The framing camera sees the whole file: every instance's centre projects into the image.
  const View view(off.cameras[0], {64, 64});
  for (size_t i = 0; i < off.instances.size(); ++i) {
    const vec3 p = view.project(off.instanceBounds(int(i)).center());
    EXPECT_TRUE(p.x > 0 && p.x < 64 && p.y > 0 && p.y < 64 && p.z > 0) << off.instances[i].name;
  }
  EXPECT_EQ(log.count({path, "no camera", "'auto'"}), 1u);
}

TEST(FileScene, InstancesAreNamedAfterTheirNodesUniquely) {
  TempDir dir;
  test::QuadScene q = test::quadScene(dir);
  q.doc["nodes"][2]["name"] = "child";  // the matrix-placed instance
  q.doc["nodes"][3].erase("name");      // the textured quad: its mesh's name
  const Scene s = loadScene(test::writeGltf(dir, q), stage(StageMode::kOff));
  std::vector<std::string> names;
  for (const Instance& i : s.instances) names.push_back(i.name);
  EXPECT_EQ(names, (std::vector<std::string>{"child", "child-2", "painted"}));
}

TEST(FileScene, FileWithoutReflectorsIsWarnedAbout) {
  TempDir dir;
  test::QuadScene q = test::cameraScene();
  q.doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.5;
  const std::string path = test::writeGltf(dir, q, "matte.gltf");
  test::LogCapture log;
  const Scene s = loadScene(path);
  EXPECT_TRUE(s.reflectorInstances().empty());
  EXPECT_EQ(log.count({"warning", path, "every method shows the same frame"}), 1u);
}

TEST(FileScene, StageIsForModelFilesOnly) {
  TempDir dir;
  const std::string json = dir.write("one.json", R"({"materials": [{"name": "m"}],
    "meshes": [{"name": "s", "procedural": "sphere"}], "instances": [{"mesh": "s", "material": "m"}]})");
  for (const std::string& spec : {std::string("gallery"), json})
    for (StageMode mode : {StageMode::kAuto, StageMode::kOn, StageMode::kOff})
      test::expectInputError([&] { loadScene(spec, stage(mode)); },
                             {"--stage", "model files only", spec});
}

}  // namespace
}  // namespace mirage
