// The viewer's camera, path recorder and event scripts: orbit keeps the distance and the pitch
// limit, fly moves eye and target alike along the view's axes, frame fits a box's sphere, a
// recording has a key per 1/30 s and ends where the camera is, playback follows the spline, and
// event scripts round-trip and name their bad fields.
#include <gtest/gtest.h>

#include "core/error.h"
#include "viewer/input.h"
#include "viewer/path_recorder.h"
#include "viewer/viewer_camera.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace mirage::test {
namespace {

CameraDesc someCamera() {
  CameraDesc c;
  c.position = {1.0f, 2.0f, 5.0f};
  c.target = {0.0f, 1.0f, 0.0f};
  c.fov_y_degrees = 50.0f;
  return c;
}

TEST(ViewerCamera, StartsAtTheSceneCameraAndOrbitsAtItsDistance) {
  ViewerCamera cam(someCamera());
  EXPECT_LT(glm::distance(cam.desc().position, someCamera().position), 1e-5f);
  const float d = glm::distance(someCamera().position, someCamera().target);
  cam.orbit({120.0f, -40.0f});
  EXPECT_NEAR(glm::distance(cam.desc().position, cam.desc().target), d, 1e-4f);
  EXPECT_EQ(cam.desc().target, someCamera().target);
  // However far it is dragged, it never looks straight down (its camera stays valid).
  cam.orbit({0.0f, 100000.0f});
  const vec3 dir = glm::normalize(cam.desc().target - cam.desc().position);
  EXPECT_LT(std::abs(dir.y), 0.9999f);
  cam.reset(someCamera());
  EXPECT_LT(glm::distance(cam.desc().position, someCamera().position), 1e-5f);
}

TEST(ViewerCamera, FliesAlongTheViewAndFramesBoxes) {
  ViewerCamera cam(someCamera());
  const CameraDesc before = cam.desc();
  const vec3 forward = glm::normalize(before.target - before.position);
  cam.fly({0.0f, 0.0f, 1.0f}, 2.0f, 0.5f);  // 1 unit forward
  const CameraDesc after = cam.desc();
  EXPECT_LT(glm::distance(after.position, before.position + forward), 1e-5f);
  EXPECT_LT(glm::distance(after.target, before.target + forward), 1e-5f);
  cam.fly({0.0f, 1.0f, 0.0f}, 1.0f, 1.0f);  // up along the world's up
  EXPECT_NEAR(cam.desc().position.y, after.position.y + 1.0f, 1e-5f);
  Bounds3 box;
  box.extend(vec3(-1.0f, 0.0f, -1.0f));
  box.extend(vec3(1.0f, 2.0f, 1.0f));
  cam.frame(box);
  const CameraDesc framed = cam.desc();
  EXPECT_LT(glm::distance(framed.target, box.center()), 1e-5f);
  // The box's bounding sphere is inside the view cone.
  const float half = glm::radians(framed.fov_y_degrees) * 0.5f;
  EXPECT_GT(std::asin(box.radius() / glm::distance(framed.position, box.center())), 0.8f * half);
  EXPECT_LT(std::asin(box.radius() / glm::distance(framed.position, box.center())), half);
}

TEST(PathRecorder, RecordsAKeyPerThirtiethAndEndsAtTheCamera) {
  PathRecorder rec;
  CameraDesc cam = someCamera();
  rec.start(cam);
  for (int f = 1; f <= 60; ++f) {  // one second at 60 frames a second
    cam.position.x += 0.01f;
    rec.record(cam, 1.0 / 60.0);
  }
  const std::optional<CameraDesc> path = rec.stop(cam);
  ASSERT_TRUE(path);
  EXPECT_GE(path->path.keys.size(), 30u);
  EXPECT_LE(path->path.keys.size(), 32u);
  for (size_t k = 1; k < path->path.keys.size(); ++k)
    EXPECT_GT(path->path.keys[k].time, path->path.keys[k - 1].time);
  EXPECT_NEAR(path->path.end(), 1.0f, 1e-5f);
  EXPECT_EQ(path->path.keys.back().position, cam.position);
  // Too short to move: no path.
  rec.start(cam);
  EXPECT_FALSE(rec.stop(cam));
  // Playback follows the path's spline and stops at its end.
  rec.play(*path);
  const std::optional<CameraDesc> at = rec.advance(0.5);
  ASSERT_TRUE(at);
  EXPECT_LT(glm::distance(at->position, path->at(0.5f).position), 1e-6f);
  EXPECT_TRUE(rec.playing());
  rec.advance(0.6);
  EXPECT_FALSE(rec.playing());
}

TEST(EventScript, RoundTripsAndNamesBadFields) {
  const std::string text = R"({"events": [
    {"frame": 0, "type": "move", "x": 10.5, "y": 20},
    {"frame": 1, "type": "button", "button": "right", "down": true},
    {"frame": 2, "type": "key", "key": "F12", "down": true},
    {"frame": 2, "type": "key", "key": "LEFT_SHIFT", "down": false},
    {"frame": 3, "type": "scroll", "y": -2}]})";
  const std::vector<ScriptedEvent> events = parseEventScript("e.json", text);
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0].event.position, vec2(10.5f, 20.0f));
  EXPECT_EQ(events[1].event.code, 1);
  EXPECT_EQ(events[2].event.code, GLFW_KEY_F12);
  EXPECT_EQ(events[3].event.code, GLFW_KEY_LEFT_SHIFT);
  EXPECT_EQ(events[4].event.position.y, -2.0f);
  const std::vector<ScriptedEvent> again = parseEventScript("again", eventScriptText(events));
  ASSERT_EQ(again.size(), events.size());
  for (size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(again[i].frame, events[i].frame);
    EXPECT_EQ(again[i].event.type, events[i].event.type);
    EXPECT_EQ(again[i].event.code, events[i].event.code);
    EXPECT_EQ(again[i].event.down, events[i].event.down);
    EXPECT_EQ(again[i].event.position, events[i].event.position);
  }
  for (char c = 'A'; c <= 'Z'; ++c)
    EXPECT_EQ(keyName(keyCode(std::string(1, c))), std::string(1, c));
  const struct {
    const char* text;
    const char* expected;
  } bad[] = {
      {R"({"events": [{"frame": 2, "type": "move", "x": 0, "y": 0},
                      {"frame": 1, "type": "move", "x": 0, "y": 0}]})",
       "events[1].frame = 1 is before"},
      {R"({"events": [{"frame": 0, "type": "jump"}]})", "events[0].type = 'jump'"},
      {R"({"events": [{"frame": 0, "type": "button", "button": "fourth", "down": true}]})",
       "left, right, middle"},
      {R"({"events": [{"frame": 0, "type": "key", "key": "W"}]})", "events[0].down is required"},
      {R"({"moves": []})", "moves: unknown field"},
  };
  for (const auto& b : bad) {
    try {
      parseEventScript("e.json", b.text);
      ADD_FAILURE() << "no error for " << b.text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(b.expected), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace mirage::test
