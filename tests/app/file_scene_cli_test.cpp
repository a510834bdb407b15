// A glTF file as a whole scene on the command line: --camera picks the file's cameras, the default
// image size follows the camera's aspect (in the viewer too), bad cameras and a misplaced --stage
// exit with 2.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/image.h"
#include "scene/gltf_scene_files.h"
#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

// The mean over pixels and channels of |a - b| (display values in [0, 1]).
double meanAbsDifference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      for (int c = 0; c < 3; ++c) sum += std::abs(a(x, y)[c] - b(x, y)[c]);
  return sum / (3.0 * a.width() * a.height());
}

double meanValue(const Image& a) {
  return meanAbsDifference(a, Image(a.width(), a.height(), vec4(0.0f)));
}

std::string sceneFile(const TempDir& dir) {
  QuadScene s = cameraScene();
  return writeGltf(dir, s, "room.gltf");
}

class FileSceneCli : public GlTest {};

TEST_F(FileSceneCli, RendersTheFilesCamerasAtTheirAspect) {
  TempDir dir;
  const std::string scene = sceneFile(dir);
  // The default size keeps its width (720) and takes its height from the camera's aspect.
  for (const auto& [camera, height] : {std::pair{"cam_a", 480}, std::pair{"cam_b", 720}}) {
    const std::string out = dir.file(std::string(camera) + ".png");
    CliResult r =
        runMirage("render --scene " + scene + " --camera " + camera + " --method none -o " + out);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(readImage(out, Encoding::kLinear).size(), ivec2(720, height)) << camera;
  }
  // At one size, through the mirror: each camera sees the scene, and each its own view of it.
  Image frames[2];
  for (int i = 0; i < 2; ++i) {
    const std::string out = dir.file(fmt::format("small{}.png", i));
    CliResult r = runMirage("render --scene " + scene + " --camera " + (i ? "cam_b" : "cam_a") +
                            " --method planar --size 160x120 -o " + out);
    ASSERT_EQ(r.code, 0) << r.output;
    frames[i] = readImage(out, Encoding::kLinear);
    EXPECT_GT(meanValue(frames[i]), 0.1) << "camera " << i << " renders (nearly) black";
  }
  // The two views differ by far more than the 1/255 steps of the PNGs.
  EXPECT_GT(meanAbsDifference(frames[0], frames[1]), 0.05);
}

// A model of many parts (the room above with 118 more boxes, 119 diffuse parts in all) renders
// with depth maps: 119 maps x 60 SRDM layers are beyond any driver's 2048 layers, so the objects
// share maps in impostor groups instead of the method falling back to envmap; per object, it
// falls back and says what would fit.
TEST_F(FileSceneCli, AModelOfManyPartsRendersWithDepthMaps) {
  TempDir dir;
  QuadScene s = cameraScene();
  nlohmann::json& nodes = s.doc["nodes"];
  nlohmann::json& roots = s.doc["scenes"][0]["nodes"];
  for (int k = 0; k < 118; ++k) {
    roots.push_back(nodes.size());
    const double x = -2.6 + 0.4 * (k % 14), z = -1.0 + 0.45 * (k / 14);
    nodes.push_back({{"name", fmt::format("part_{}", k)},
                     {"mesh", 1},
                     {"translation", {x, 0.1, z}},
                     {"scale", {0.2, 0.2, 0.2}}});
  }
  const std::string scene = writeGltf(dir, s, "parts.gltf");
  const std::string out = dir.file("parts.png");
  CliResult r = runMirage("render --scene " + scene +
                          " --camera cam_a --method depthmap --size 96x64 -o " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("cannot run on this OpenGL driver"), std::string::npos) << r.output;
  r = runMirage("render --scene " + scene +
                    " --camera cam_a --method depthmap --impostor-groups per-object --size 96x64 -o " +
                    out,
                "", kFallbackExpected);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("--impostor-groups auto (34 groups) would fit"), std::string::npos)
      << r.output;
  r = runMirage("render --scene " + scene + " --method depthmap --impostor-groups some -o " + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--impostor-groups 'some' is not allowed"), std::string::npos)
      << r.output;
}

TEST_F(FileSceneCli, GivenSizeWins) {
  TempDir dir;
  const std::string out = dir.file("a.png");
  CliResult r = runMirage("render --scene " + sceneFile(dir) +
                          " --camera cam_a --method none --size 64x64 -o " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(readImage(out, Encoding::kLinear).size(), ivec2(64, 64));
}

// The viewer opens the file as a scene too, at the chosen camera's aspect, and its screenshot is
// the headless render of the camera it wrote beside it (ctest runs this under Xvfb).
TEST(ViewUnderXvfb, FileSceneOpensAtItsCamera) {
  MIRAGE_NEED_DISPLAY();
  TempDir dir;
  const std::string common = " --scene " + sceneFile(dir) + " --method planar --order 1";
  const CliResult v = runMirage("view" + common + " --camera cam_a --frames 2 --screenshot " +
                                dir.file("view.png"));
  ASSERT_EQ(v.code, 0) << v.output;
  const Image shot = readImage(dir.file("view.png"));
  EXPECT_EQ(shot.size(), ivec2(720, 480));
  const CliResult r = runMirage("render" + common + " --size 720x480 --camera-path " +
                                dir.file("view.camera.json") + " -o " + dir.file("render.png"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_LT(meanAbsDifference(shot, readImage(dir.file("render.png"))), 0.01);
}

TEST(FileSceneCliInput, UnknownCameraListsTheFilesCameras) {
  TempDir dir;
  CliResult r = runMirage("render --scene " + sceneFile(dir) + " --camera nope --method none -o " +
                          dir.file("x.png"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("no camera 'nope' (it has: cam_a, cam_b)"), std::string::npos)
      << r.output;
}

TEST(FileSceneCliInput, BadYfovNamesTheFileTheCameraAndTheField) {
  TempDir dir;
  QuadScene s = cameraScene();
  s.doc["cameras"][1]["perspective"]["yfov"] = 4.0;
  const std::string scene = writeGltf(dir, s, "wide.gltf");
  CliResult r = runMirage("render --scene " + scene + " --method none -o " + dir.file("x.png"));
  EXPECT_EQ(r.code, 2) << r.output;
  for (const std::string& part : {scene, std::string("camera 'cam_b'"),
                                  std::string("perspective.yfov = 4"), std::string("(0, 3.14159)")})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
}

TEST(FileSceneCliInput, StageIsForModelFilesOnly) {
  TempDir dir;
  CliResult r =
      runMirage("render --stage on --scene gallery --method none -o " + dir.file("x.png"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--stage on applies to model files only"), std::string::npos) << r.output;
  r = runMirage("render --stage sometimes --scene " + sceneFile(dir) + " --method none -o " +
                dir.file("x.png"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--stage sometimes: allowed auto|on|off"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace mirage::test
