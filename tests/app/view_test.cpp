// `mirage view`: without a display it says so and exits 2; bad input exits 2 naming the file or
// the option. Under Xvfb (ctest's "ViewUnderXvfb"): its screenshot is the headless renderer's
// frame of the same camera and time (the camera file written beside it reproduces both); events
// replayed from a script move the camera as a user would, and the recorded path plays back in
// the viewer and in `mirage render` alike; switching methods over and over leaks no GL object;
// the ground truth's split shows the method left and the reference right, and its PSNR is
// compare's.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/image.h"
#include "eval/metrics.h"
#include "methods/method.h"
#include "scene/camera_file.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/test_files.h"
#include "viewer/input.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

// The two PNG files' 8-bit values differ by at most one step: what the window showed went
// through the display transform on the GPU (viewer/display.frag), `render`'s PNG through the
// same formulas on the CPU (shading/tonemap.h), which round alike but for an ulp at a step's
// edge (docs/viewer.md).
::testing::AssertionResult withinOneStep(const fs::path& a, const fs::path& b) {
  return imagesEqual(readImage(a.string(), Encoding::kLinear),
                     readImage(b.string(), Encoding::kLinear), 1.0f / 255.0f + kFloatRounding,
                     nullptr, a.stem().string() + "-vs-" + b.stem().string());
}

// The two EXR files hold the same linear frame to the bit.
::testing::AssertionResult sameFrame(const fs::path& a, const fs::path& b) {
  return imagesEqual(readImage(a.string()), readImage(b.string()), 0.0f, nullptr,
                     a.stem().string() + "-vs-" + b.stem().string());
}

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

vec3 vec3Of(const nlohmann::json& v) {
  return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
}

TEST(ViewCli, WithoutDisplayExitsTwoAndSaysSo) {
  const auto dir = testTempDir("view-nodisplay");
  const CliResult r =
      runMirage("view --scene mirror-room --frames 1 --screenshot " + (dir / "v.png").string(),
                "env -u DISPLAY");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("xvfb-run"), std::string::npos) << r.output;
}

TEST(ViewCli, BadInputExitsTwoNamingTheProblem) {
  const auto dir = testTempDir("view-bad");
  writeText(dir / "path.json",
            R"({"path": [{"time": 0, "position": [0, 1, 2], "target": [0, 1, 0]}]})");
  writeText(dir / "still.json", R"({"position": [0, 1, 2], "target": [0, 1, 0]})");
  writeText(dir / "events.json",
            R"({"events": [{"frame": 1, "type": "key", "key": "WUT", "down": true}]})");
  const struct {
    std::string args, expected;
  } cases[] = {
      {"view --scene mirror-room --method nosuch --frames 1", "unknown method 'nosuch'"},
      {"view --scene mirror-room --frames -1", "0..1000000"},
      {"view --scene mirror-room --screenshot " + (dir / "v.png").string(), "needs --frames"},
      {"view --scene mirror-room --truth sideways", "off|split|flip"},
      {"view --scene mirror-room --truth-resolution 9", "1..8"},
      {"view --scene mirror-room --camera-path " + (dir / "path.json").string(),
       (dir / "path.json").string() + ": path has 1 key"},
      {"view --scene mirror-room --play-path " + (dir / "still.json").string() + " --frames 2",
       "has no path"},
      {"view --scene mirror-room --events " + (dir / "events.json").string(),
       (dir / "events.json").string() + ": events[0].key = 'WUT' is not a key name"},
  };
  for (const auto& c : cases) {
    // A display is not needed to be told the input is bad (and under Xvfb none opens).
    const CliResult r = runMirage(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
}

// The viewer's frame is the headless renderer's: the same FrameRenderer; the camera file beside
// the screenshot holds the camera and the scene time (mirror-room moves while the viewer runs).
TEST(ViewUnderXvfb, ScreenshotMatchesTheHeadlessRender) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-shot");
  for (const char* method : {"envmap", "planar", "zexel"}) {
    const std::string common =
        std::string(" --scene mirror-room --size 320x240 --order 1 --method ") + method;
    for (const char* ext : {".png", ".exr"}) {
      const CliResult v = runMirage("view" + common + " --frames 4 --screenshot " +
                                    (dir / (std::string("view") + ext)).string());
      ASSERT_EQ(v.code, 0) << v.output;
    }
    const CameraFile shot = loadCameraFile((dir / "view.camera.json").string());
    ASSERT_TRUE(shot.time.has_value());
    EXPECT_NEAR(*shot.time, 3.0f / 60.0f, 1e-6f);  // three 1/60 s steps after the first frame
    for (const char* ext : {".png", ".exr"}) {
      const CliResult r =
          runMirage("render" + common + " --camera-path " + (dir / "view.camera.json").string() +
                    " -o " + (dir / (std::string("render") + ext)).string());
      ASSERT_EQ(r.code, 0) << r.output;
    }
    EXPECT_TRUE(sameFrame(dir / "view.exr", dir / "render.exr")) << method;
    EXPECT_TRUE(withinOneStep(dir / "view.png", dir / "render.png")) << method;
  }
}

// A script drags (orbit), flies forward (W held for 10 frames), pans and dollies; the camera
// is recorded along the way. The shot equals the headless render of its camera file; the
// recorded path ends at that camera, and played back in the viewer it reaches the frame that
// `mirage render --camera-path` draws at the same path time.
// A supersampled frame beyond the driver's largest frame side is refused with exit 2, naming
// --ssaa and the sizes, before anything is drawn or written.
TEST(ViewUnderXvfb, SupersamplingBeyondTheDriverIsAnInputError) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-ssaa");
  const CliResult r = runMirage(
      "view --scene sphere-over-checker --size 4200x2400 --ssaa 8 --frames 2 --screenshot " +
      (dir / "shot.png").string());
  EXPECT_EQ(r.code, 2) << r.output;
  // 33600 pixels: beyond every driver (GL caps frame sides at 32768 at most in practice).
  EXPECT_NE(r.output.find("--ssaa 8: a 4200x2400 window needs a 33600x19200 frame"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "shot.png"));
}

TEST(ViewUnderXvfb, ReplayedEventsRecordAPathThatPlaysBackAlike) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-events");
  writeText(dir / "events.json", R"({"events": [
    {"frame": 1, "type": "move", "x": 200, "y": 120},
    {"frame": 2, "type": "button", "button": "left", "down": true},
    {"frame": 3, "type": "move", "x": 240, "y": 130},
    {"frame": 4, "type": "move", "x": 270, "y": 128},
    {"frame": 5, "type": "button", "button": "left", "down": false},
    {"frame": 6, "type": "key", "key": "W", "down": true},
    {"frame": 16, "type": "key", "key": "W", "down": false},
    {"frame": 17, "type": "button", "button": "right", "down": true},
    {"frame": 18, "type": "move", "x": 250, "y": 140},
    {"frame": 19, "type": "button", "button": "right", "down": false},
    {"frame": 20, "type": "scroll", "y": 2}]})");
  const std::string common = " --scene teapot-sphere --size 320x240 --order 1 --method envmap";
  CliResult v =
      runMirage("view" + common + " --frames 24 --events " + (dir / "events.json").string() +
                " --record-path " + (dir / "walk.json").string() + " --screenshot " +
                (dir / "shot.png").string());
  ASSERT_EQ(v.code, 0) << v.output;
  const CameraFile shot = loadCameraFile((dir / "shot.camera.json").string());
  const CameraFile walk = loadCameraFile((dir / "walk.json").string());
  // The events moved the camera away from the scene's.
  const CameraFile start =
      parseCameraFile("main", R"({"position": [0, 1.7, 4.6], "target": [0, 0.8, -0.3]})");
  EXPECT_GT(glm::distance(shot.camera.position, start.camera.position), 0.3f);
  ASSERT_GE(walk.camera.path.keys.size(), 10u);
  const float end = walk.camera.path.end();
  EXPECT_NEAR(end, 23.0f / 60.0f, 1e-4f);
  EXPECT_LT(glm::distance(walk.camera.at(end).position, shot.camera.position), 1e-4f);
  // The shot is the headless frame of its camera.
  CliResult r = runMirage("render" + common + " --camera-path " +
                          (dir / "shot.camera.json").string() + " -o " + (dir / "a.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(withinOneStep(dir / "shot.png", dir / "a.png"));
  // Played back for 16 frames, the viewer is at path time 15/60: what render draws there.
  v = runMirage("view" + common + " --frames 16 --play-path " + (dir / "walk.json").string() +
                " --screenshot " + (dir / "played.png").string());
  ASSERT_EQ(v.code, 0) << v.output;
  r = runMirage("render" + common + " --camera-path " + (dir / "walk.json").string() +
                " --time 0.25 -o " + (dir / "b.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(withinOneStep(dir / "played.png", dir / "b.png"));
}

// Every method three times (back to the first), a frame of each:
// the handles mirage holds at the last frame are those of the first, and the objects GL itself
// reports (asked about every name) after each switch of the third round are those of the same
// switch in the second: a leak would grow them every round. (Mesa holds on to a program deleted
// while its state still refers to it until another replaces it there, so the first round can
// differ from the later ones by such a program: measured, rounds 2, 3 and 4 are identical.)
TEST(ViewUnderXvfb, SwitchingMethodsLeaksNoGlObjects) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-leaks");
  std::string events = R"({"events": [)";
  const int switches = 3 * int(methodNames().size());
  for (int k = 0; k < switches; ++k)
    events += fmt::format(R"({}{{"frame": {}, "type": "key", "key": "M", "down": true}},
                             {{"frame": {}, "type": "key", "key": "M", "down": false}})",
                          k ? "," : "", 2 * k + 1, 2 * k + 1);
  writeText(dir / "events.json", events + "]}");
  const CliResult v = runMirage(
      "view --scene sphere-over-checker --size 160x120 --order 1 --method none --frames " +
      std::to_string(2 * switches + 3) + " --events " + (dir / "events.json").string() +
      " --report " + (dir / "report.json").string());
  ASSERT_EQ(v.code, 0) << v.output;
  const nlohmann::json j = readJson(dir / "report.json");
  EXPECT_EQ(j["method"], "none");
  EXPECT_EQ(j["methods_shown"].size(), size_t(switches + 1)) << j["methods_shown"];
  EXPECT_EQ(j["gl_handles"]["first_frame"], j["gl_handles"]["last_frame"]);
  const nlohmann::json& after = j["gl_objects_after_switch"];
  ASSERT_EQ(after.size(), size_t(switches));
  const int round = switches / 3;
  for (int k = round; k < 2 * round; ++k) {
    EXPECT_EQ(after[k]["method"], after[k + round]["method"]);
    EXPECT_EQ(after[k]["gl_objects"], after[k + round]["gl_objects"]) << after[k]["method"];
  }
  const int first = j["gl_objects"]["first_frame"]["total"].get<int>();
  EXPECT_GT(first, 10);
  EXPECT_LE(j["gl_objects"]["last_frame"]["total"].get<int>(), first + 1);
}

// Real input through the window: xdotool (X's XTEST extension) moves the pointer over the
// viewer, presses keys and finally Escape; GLFW's callbacks (chained behind Dear ImGui's) queue
// them, the viewer acts on them (W flies, Escape closes the window) and --record-events writes
// them: the window's path of input works, not only scripts.
TEST(ViewUnderXvfb, WindowInputReachesTheViewer) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-xdotool");
  const std::string viewer = fmt::format(
      "timeout 120 {} view --scene sphere-over-checker --size 160x120 --method none --pause "
      "--frames 100000 --record-events {} --report {} > {} 2>&1",
      MIRAGE_BINARY, (dir / "events.json").string(), (dir / "report.json").string(),
      (dir / "viewer.log").string());
  // The window is found by its title once it is viewable; every xdotool step is bounded, and
  // Escape ends the run. Focusing a window the server has created but not yet mapped fails
  // (BadMatch from XSetInputFocus, which ends xdotool), so the focus is retried until it holds.
  const std::string find = "xdotool search --sync --onlyvisible --name 'sphere-over-checker'";
  const std::string input = fmt::format(
      "timeout 60 sh -c \"until {0} windowfocus --sync; do sleep 0.2; done\" && "
      "timeout 60 {0} mousemove --window %1 120 90 sleep 0.3 keydown w sleep 1.0 keyup w "
      "sleep 0.3 key Escape",
      find);
  const int status =
      std::system(fmt::format("({} & pid=$!; {} || kill $pid; wait $pid)", viewer, input).c_str());
  ASSERT_EQ(status, 0) << readFile((dir / "viewer.log").string());
  const std::vector<ScriptedEvent> events = loadEventScript((dir / "events.json").string());
  bool w_down = false, w_up = false, escape = false, moved = false;
  for (const ScriptedEvent& e : events) {
    if (e.event.type == InputEvent::Type::kKey && keyName(e.event.code) == "W")
      (e.event.down ? w_down : w_up) = true;
    if (e.event.type == InputEvent::Type::kKey && keyName(e.event.code) == "ESCAPE") escape = true;
    if (e.event.type == InputEvent::Type::kMove) moved = true;
  }
  EXPECT_TRUE(w_down && w_up && escape && moved) << readFile((dir / "events.json").string());
  // Flying forward for a second moved the camera toward the scene (held half a second, a loaded
  // sanitizer run once covered 0.47: the viewer's frames were slower than its step cap).
  const nlohmann::json j = readJson(dir / "report.json");
  const vec3 start(0.0f, 2.6f, 6.5f);
  const vec3 now = vec3Of(j["camera"]["position"]);
  EXPECT_GT(glm::distance(start, now), 0.5f);
  EXPECT_LT(j["frames"].get<int>(), 100000);  // Escape ended it
}

// A click (press and release without a drag) selects what is under the cursor, traced against
// the scene; F frames it: the camera then looks at the centre of its bounds.
TEST(ViewUnderXvfb, ClickSelectsAndFFramesTheSelection) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-select");
  // sphere-over-checker's mirror sphere sits in the middle of the main camera's view.
  writeText(dir / "events.json", R"({"events": [
    {"frame": 1, "type": "move", "x": 160, "y": 120},
    {"frame": 2, "type": "button", "button": "left", "down": true},
    {"frame": 3, "type": "button", "button": "left", "down": false},
    {"frame": 4, "type": "key", "key": "F", "down": true},
    {"frame": 4, "type": "key", "key": "F", "down": false}]})");
  const CliResult v = runMirage(
      "view --scene sphere-over-checker --size 320x240 --method none --frames 6 --events " +
      (dir / "events.json").string() + " --report " + (dir / "report.json").string());
  ASSERT_EQ(v.code, 0) << v.output;
  const nlohmann::json j = readJson(dir / "report.json");
  EXPECT_EQ(j["selected"], "mirror-sphere");
  const vec3 target = vec3Of(j["camera"]["target"]);
  EXPECT_LT(glm::distance(target, vec3(0.0f, 1.25f, 0.0f)), 1e-4f);  // the sphere's centre
}

// F12 writes the frame as shown and its camera into --screenshot-dir (numbered, never over an
// earlier shot), and a resize re-makes the frame at the window's new size.
TEST(ViewUnderXvfb, F12WritesShotsAndResizingRendersAtTheNewSize) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-f12");
  writeText(dir / "events.json", R"({"events": [
    {"frame": 2, "type": "key", "key": "F12", "down": true},
    {"frame": 3, "type": "key", "key": "F12", "down": false},
    {"frame": 4, "type": "resize", "width": 200, "height": 150},
    {"frame": 8, "type": "key", "key": "F12", "down": true},
    {"frame": 8, "type": "key", "key": "F12", "down": false}]})");
  const std::string common = " --scene sphere-over-checker --order 1 --method envmap";
  const CliResult v =
      runMirage("view" + common + " --size 320x240 --frames 10 --events " +
                (dir / "events.json").string() + " --screenshot-dir " + (dir / "shots").string() +
                " --report " + (dir / "report.json").string());
  ASSERT_EQ(v.code, 0) << v.output;
  const fs::path first = dir / "shots" / "sphere-over-checker-envmap-1.png";
  const fs::path second = dir / "shots" / "sphere-over-checker-envmap-2.png";
  ASSERT_TRUE(fs::exists(first)) << v.output;
  ASSERT_TRUE(fs::exists(second)) << v.output;
  EXPECT_EQ(readImage(first.string()).width(), 320);
  const Image small = readImage(second.string());
  EXPECT_EQ(small.width(), 200);
  EXPECT_EQ(small.height(), 150);
  EXPECT_EQ(readJson(dir / "report.json")["size"], nlohmann::json::array({200, 150}));
  // Each shot is `render`'s frame of its camera file at its size.
  const CliResult r =
      runMirage("render" + common + " --size 200x150 --camera-path " +
                (dir / "shots" / "sphere-over-checker-envmap-2.camera.json").string() + " -o " +
                (dir / "r.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(withinOneStep(second, dir / "r.png"));
}

// The split shows the method left of the line and the reference right of it: with --ssaa 2 and
// the reference at full resolution, the halves are `render --ssaa 2`'s frame of the method and the
// ray tracer's at 4 samples (its 2 x 2 strata centres: the frame's sub-pixels), and the PSNR the
// viewer reports is that of `compare --ssaa 2` (matched sampling).
TEST(ViewUnderXvfb, GroundTruthSplitAndPsnrAreTheHeadlessOnes) {
  MIRAGE_NEED_DISPLAY();
  const auto dir = testTempDir("view-truth");
  const std::string scene = " --scene sphere-over-checker --size 240x160 --order 1";
  const CliResult v =
      runMirage("view" + scene +
                " --method envmap --frames 3 --truth split --truth-resolution 1 --ssaa 2 "
                "--screenshot " +
                (dir / "split.png").string() + " --report " + (dir / "report.json").string());
  ASSERT_EQ(v.code, 0) << v.output;
  ASSERT_EQ(
      runMirage("render" + scene + " --method envmap --ssaa 2 -o " + (dir / "m.png").string()).code,
      0);
  ASSERT_EQ(
      runMirage("render" + scene + " --method raytrace --spp 4 -o " + (dir / "t.png").string())
          .code,
      0);
  const Image shot = readImage((dir / "split.png").string());
  const Image method = readImage((dir / "m.png").string()),
              truth = readImage((dir / "t.png").string());
  ASSERT_EQ(shot.width(), 240);
  double left = 0.0, right = 0.0;
  int nl = 0, nr = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 240; ++x) {
      if (std::abs(x + 0.5f - 120.0f) < 2.0f) continue;  // the line
      const vec3 s(shot(x, y));
      if (x < 120) {
        left += double(glm::length(s - vec3(method(x, y))));
        ++nl;
      } else {
        right += double(glm::length(s - vec3(truth(x, y))));
        ++nr;
      }
    }
  EXPECT_LT(left / nl, 2e-3);
  EXPECT_LT(right / nr, 2e-3);
  const nlohmann::json j = readJson(dir / "report.json");
  EXPECT_EQ(j["truth"]["level"], 3);
  const CliResult c = runMirage("compare" + scene + " --methods envmap,raytrace --ssaa 2 -o " +
                                (dir / "cmp").string());
  ASSERT_EQ(c.code, 0) << c.output;
  const nlohmann::json m = readJson(dir / "cmp" / "metrics.json");
  ASSERT_TRUE(j["psnr_reflector"].is_number()) << j;
  EXPECT_NEAR(j["psnr_reflector"].get<double>(),
              m["methods"]["envmap"]["psnr_reflector"].get<double>(), 0.05);
}

}  // namespace
}  // namespace mirage::test
