#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "core/display.h"
#include "core/image.h"

namespace mirage {
namespace {

std::filesystem::path tempPath(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "mirage-image-test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(ImageIo, ExrRoundTripsHalfFloats) {
  Image img(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) img(x, y) = vec4(float(x) * 0.25f, float(y) * 100.0f, 0.5f, 1.0f);
  auto path = tempPath("rt.exr").string();
  writeExr(path, img);
  Image back = readImage(path);
  ASSERT_EQ(back.size(), img.size());
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) EXPECT_EQ(back(x, y), img(x, y));  // all exactly representable
}

TEST(ImageIo, PngRoundTripsThroughSrgb) {
  Image display(4, 2, vec4(0.0f, 0.5f, 1.0f, 1.0f));
  auto path = tempPath("rt.png").string();
  writePng(path, display);
  Image linear = readImage(path, Encoding::kSrgb);
  EXPECT_NEAR(linear(0, 0).y, srgbToLinear(128.0f / 255.0f), 1e-6f);
  Image raw = readImage(path, Encoding::kLinear);
  EXPECT_NEAR(raw(3, 1).y, 128.0f / 255.0f, 1e-6f);
  EXPECT_FLOAT_EQ(raw(3, 1).z, 1.0f);
}

TEST(ImageIo, BadFilesNameTheFile) {
  auto path = tempPath("garbage.png").string();
  writeFileAtomic(path, "this is not an image");
  try {
    readImage(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("garbage.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readImage(tempPath("missing.exr").string()), InputError);
  // A truncated EXR: the magic number and nothing else.
  auto exr = tempPath("truncated.exr").string();
  writeFileAtomic(exr, std::string("\x76\x2f\x31\x01\x02\x00", 6));
  EXPECT_THROW(readImage(exr), InputError);
}

TEST(ImageIo, WriteImageChoosesFormatByExtension) {
  Image img(2, 2, vec4(0.25f, 0.5f, 2.0f, 7.0f));
  EXPECT_THROW(writeImage(tempPath("x.bmp").string(), img, {}), InputError);
  writeImage(tempPath("x.exr").string(), img, {});
  Image back = readImage(tempPath("x.exr").string());
  EXPECT_EQ(back(1, 1), vec4(0.25f, 0.5f, 2.0f, 1.0f));  // linear kept, alpha reset
}

TEST(AtomicFile, LeavesNoTemporaryBehindWhenNotCommitted) {
  auto dir = tempPath("atomic");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    AtomicFile f((dir / "out.txt").string());
    std::ofstream(f.tempPath()) << "partial";
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  writeFileAtomic((dir / "out.txt").string(), "whole");
  EXPECT_EQ(readFile((dir / "out.txt").string()), "whole");
}

}  // namespace
}  // namespace mirage
