// Frame sequences and camera files on the command line: `render --frames N --fps F` writes one
// image per time (the scene moving between them), an MP4 through ffmpeg or a clear error without
// it; a camera file (a still camera or a recorded path) replaces the scene's cameras in render and
// bench; `bench --fps` plays the scene and reports what every method redid per frame.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/display.h"
#include "core/image.h"
#include "eval/metrics.h"
#include "scene/camera_file.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

class SequenceCli : public GlTest {};

double psnrBetween(const fs::path& a, const fs::path& b) {
  return psnrFromMse(meanSquaredError(readImage(a.string()), readImage(b.string())));
}

TEST_F(SequenceCli, FramesAreWrittenPerTimeAndEqualSingleRendersAtThoseTimes) {
  const fs::path dir = testTempDir("seq");
  CliResult r = runMirage(
      "render --scene ripple-pool --method envmap --size 96x64 --frames 3 "
      "--fps 4 --time 0.5 -o " +
      (dir / "f.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(fs::exists(dir / fmt::format("f_000{}.png", i))) << i;
  EXPECT_FALSE(fs::exists(dir / "f.png"));
  // Frame 2 is the scene at 0.5 + 2 / 4 = 1.0 s: the same pixels as one render at --time 1.
  r = runMirage("render --scene ripple-pool --method envmap --size 96x64 --time 1 -o " +
                (dir / "one.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::isinf(psnrBetween(dir / "f_0002.png", dir / "one.png")));
  // The pool ripples from frame to frame.
  EXPECT_LT(psnrBetween(dir / "f_0000.png", dir / "f_0001.png"), 45.0);
}

TEST_F(SequenceCli, Mp4GoesThroughFfmpegOrSaysItIsMissing) {
  const fs::path dir = testTempDir("seq");
  // Without ffmpeg on PATH: exit 2 before anything is rendered, and nothing written.
  CliResult r = runMirage("render --scene ripple-pool --method none --size 64x48 --frames 3 -o " +
                              (dir / "v.mp4").string(),
                          "PATH=/nonexistent");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("ffmpeg was not found"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
  // A failing ffmpeg: its status reported, exit 1, no half-written video, no frames left over.
  r = runMirage("render --scene ripple-pool --method none --size 64x48 --frames 3 -o " +
                    (dir / "v.mp4").string(),
                "MIRAGE_FFMPEG=/bin/false");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("ffmpeg (/bin/false) failed"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
  // scripts/setup installs ffmpeg: the real thing makes a real video.
  r = runMirage("render --scene ripple-pool --method none --size 65x49 --frames 6 --fps 12 -o " +
                (dir / "v.mp4").string());
  ASSERT_EQ(r.code, 0) << r.output;
  ASSERT_TRUE(fs::exists(dir / "v.mp4"));
  std::ifstream in(dir / "v.mp4", std::ios::binary);
  std::string head(12, '\0');
  in.read(head.data(), 12);
  EXPECT_EQ(head.substr(4, 4), "ftyp");  // an ISO media file
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);  // the frames' folder is gone
}

TEST_F(SequenceCli, CameraFileReplacesTheScenesCamera) {
  const fs::path dir = testTempDir("seq");
  // A still camera file equal to the scene's camera gives the same image as the scene's camera.
  CameraDesc main;
  main.name = "copy";
  main.position = {0.0f, 2.6f, 6.5f};
  main.target = {0.0f, 1.0f, 0.0f};
  saveCameraFile((dir / "cam.json").string(), main);
  const std::string base = "render --scene sphere-over-checker --method envmap --size 96x64 ";
  ASSERT_EQ(runMirage(base + "-o " + (dir / "a.png").string()).code, 0);
  CliResult r = runMirage(base + "--camera-path " + (dir / "cam.json").string() + " -o " +
                          (dir / "b.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::isinf(psnrBetween(dir / "a.png", dir / "b.png")));
  // A path: at --time 2 the camera is at its second key.
  CameraDesc walk = main;
  walk.path.keys = {{0.0f, {4.0f, 2.0f, 4.0f}, {0.0f, 1.0f, 0.0f}},
                    {2.0f, {0.0f, 2.6f, 6.5f}, {0.0f, 1.0f, 0.0f}}};
  saveCameraFile((dir / "walk.json").string(), walk);
  r = runMirage(base + "--camera-path " + (dir / "walk.json").string() + " --time 2 -o " +
                (dir / "c.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::isinf(psnrBetween(dir / "a.png", dir / "c.png")));
  // --camera and --camera-path exclude each other; a bad file names itself and the field.
  r = runMirage(base + "--camera main --camera-path " + (dir / "cam.json").string() + " -o x.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("give one of them"), std::string::npos) << r.output;
  writeText(dir / "bad.json", R"({"position": [0, 1, 2], "target": [0, 1, 2]})");
  r = runMirage(base + "--camera-path " + (dir / "bad.json").string() + " -o x.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find((dir / "bad.json").string() + ": target equals the position"),
            std::string::npos)
      << r.output;
}

TEST_F(SequenceCli, BenchPlaysTheSceneAndCountsWhatEachMethodRedid) {
  const fs::path dir = testTempDir("seq");
  const fs::path json = dir / "b.json";
  CliResult r = runMirage(
      "bench --scene mirror-room --methods none,envmap,raytrace --fps 30 --frames 4 --warmup 1 "
      "--size 96x64 --json " +
      json.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["fps"], 30.0);
  EXPECT_TRUE(j.contains("scene_update_ms"));
  // Every timed frame is a new time: the teapot, the box and the light moved each time.
  EXPECT_EQ(j["methods"]["envmap"]["counts_per_frame"]["cube_captures"], 1.0);
  EXPECT_EQ(j["methods"]["raytrace"]["counts_per_frame"]["bvh_builds"], 1.0);
  EXPECT_TRUE(j["methods"]["none"]["ms_parts_p95"].contains("update"));
  // A camera file's path is played along with the scene.
  CameraDesc walk;
  walk.name = "walked";
  walk.path.keys = {{0.0f, {2.8f, 1.7f, 3.2f}, {-0.8f, 1.4f, -3.0f}},
                    {1.0f, {1.2f, 1.65f, 2.4f}, {-0.6f, 1.4f, -3.2f}}};
  saveCameraFile((dir / "walk.json").string(), walk);
  r = runMirage(
      "bench --scene mirror-room --methods none --fps 30 --frames 3 --warmup 1 "
      "--size 96x64 --camera-path " +
      (dir / "walk.json").string() + " --json " + json.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream walked(json);
  EXPECT_EQ(nlohmann::json::parse(walked)["camera"], "walked");
  // Still (no --fps): nothing is redone after the warm-up.
  r = runMirage(
      "bench --scene mirror-room --methods envmap --frames 3 --warmup 1 --size 96x64 --json " +
      json.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream again(json);
  const nlohmann::json still = nlohmann::json::parse(again);
  EXPECT_EQ(still["methods"]["envmap"]["counts_per_frame"]["cube_captures"], 0.0);
}

}  // namespace
}  // namespace mirage::test
