// Camera files round-trip exactly (every float reads back to itself, paths key for key), and a
// malformed one is an InputError naming the file and the field.
#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/camera_file.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

TEST(CameraFile, StillAndPathCamerasRoundTripExactly) {
  CameraDesc still;
  still.name = "shot";
  still.position = {0.1f, 1.0f / 3.0f, -7.123456789f};
  still.target = {1e-7f, 2.5f, 3.0f};
  still.up = {0.0f, 1.0f, 0.1f};
  still.fov_y_degrees = 47.3f;
  still.near_plane = 0.0123f;
  still.far_plane = 345.6f;
  CameraDesc path = still;
  path.name = "recorded";
  for (int k = 0; k < 50; ++k)
    path.path.keys.push_back({float(k) / 60.0f,
                              {std::sin(0.1f * float(k)), 1.7f, 3.0f + 0.01f * float(k)},
                              {0.0f, 1.0f + 1e-3f * float(k), 0.0f}});
  path.position = path.path.keys.front().position;
  path.target = path.path.keys.front().target;
  const auto dir = testTempDir("camera-file");
  for (const CameraDesc& c : {still, path}) {
    const std::string file = (dir / (c.name + ".json")).string();
    saveCameraFile(file, c, 2.25f);
    const CameraFile read = loadCameraFile(file);
    const CameraDesc& back = read.camera;
    EXPECT_EQ(read.time, 2.25f);
    EXPECT_EQ(back.name, c.name);
    EXPECT_EQ(back.position, c.position);
    EXPECT_EQ(back.target, c.target);
    EXPECT_EQ(back.up, c.up);
    EXPECT_EQ(back.fov_y_degrees, c.fov_y_degrees);
    EXPECT_EQ(back.near_plane, c.near_plane);
    EXPECT_EQ(back.far_plane, c.far_plane);
    ASSERT_EQ(back.path.keys.size(), c.path.keys.size());
    for (size_t k = 0; k < c.path.keys.size(); ++k) {
      EXPECT_EQ(back.path.keys[k].time, c.path.keys[k].time);
      EXPECT_EQ(back.path.keys[k].position, c.path.keys[k].position);
      EXPECT_EQ(back.path.keys[k].target, c.path.keys[k].target);
    }
    // Written again, the text is the same: nothing drifts through a round trip.
    EXPECT_EQ(cameraFileText(back, read.time), cameraFileText(c, 2.25f));
  }
}

TEST(CameraFile, MalformedFilesNameTheFileAndTheField) {
  const struct {
    const char* text;
    const char* expected;
  } cases[] = {
      {"", "is empty"},
      {"[1, 2]", "object"},
      {R"({"position": [0, 0, 0]})", "target"},
      {R"({"position": [0, 0, 0], "target": [0, 0, 1], "fov_y": 190})", "fov_y"},
      {R"({"path": [{"time": 0, "position": [0, 0, 0], "target": [0, 0, 1]}]})", "at least 2"},
      {R"({"path": [{"time": 1, "position": [0, 0, 0], "target": [0, 0, 1]},
                    {"time": 1, "position": [1, 0, 0], "target": [0, 0, 1]}]})",
       "must be greater"},
      {R"({"position": [0, 0, 0], "target": [0, 0, 1], "zoom": 2})", "zoom: unknown field"},
      {R"({"position": [0, 0, 0], "target": [0, 0, 1], "time": -1})", "time = -1"},
  };
  for (const auto& c : cases) {
    try {
      parseCameraFile("cam.json", c.text);
      ADD_FAILURE() << "no error for " << c.text;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind("cam.json", 0), 0u) << msg;
      EXPECT_NE(msg.find(c.expected), std::string::npos) << msg;
    }
  }
}

}  // namespace
}  // namespace mirage::test
