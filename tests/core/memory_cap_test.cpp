// --max-memory: sizes parse and print, and what a file's header asks for is refused before it is
// allocated (images, meshes, gzip streams), with a message naming the file and the cap.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/image.h"
#include "core/memory_cap.h"
#include "scene/loader_support.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"
#include "support/test_files.h"

namespace mirage {
namespace {

using test::expectInputError;

// Sets the process's cap for one test and puts the default back.
struct CapFor {
  explicit CapFor(uint64_t bytes) { setMaxMemory(bytes); }
  ~CapFor() { setMaxMemory(kDefaultMaxMemory); }
};

TEST(MemoryCap, SizesParseInBinaryUnits) {
  EXPECT_EQ(parseByteSize("--max-memory", "4G"), uint64_t(4) << 30);
  EXPECT_EQ(parseByteSize("--max-memory", "512M"), uint64_t(512) << 20);
  EXPECT_EQ(parseByteSize("--max-memory", "512MiB"), uint64_t(512) << 20);
  EXPECT_EQ(parseByteSize("--max-memory", "1.5g"), uint64_t(3) << 29);
  EXPECT_EQ(parseByteSize("--max-memory", "2048k"), uint64_t(2) << 20);
  EXPECT_EQ(parseByteSize("--max-memory", "1048576"), uint64_t(1) << 20);
  EXPECT_EQ(parseByteSize("--max-memory", "1T"), uint64_t(1) << 40);
  for (const char* bad : {"", "G", "abc", "4X", "-1G", "0", "64k", "2T", "nan", "infG", "4 G"})
    expectInputError([&] { parseByteSize("--max-memory", bad); }, {"--max-memory", "1M..1T"});
}

TEST(MemoryCap, BytesPrintForPeople) {
  EXPECT_EQ(formatBytes(100), "100 B");
  EXPECT_EQ(formatBytes(12 << 10), "12 KiB");
  EXPECT_EQ(formatBytes(uint64_t(3) << 29), "1.5 GiB");
  EXPECT_EQ(formatBytes(uint64_t(4) << 30), "4.0 GiB");
  EXPECT_EQ(saturatingMul(uint64_t(1) << 40, uint64_t(1) << 40), UINT64_MAX);
  EXPECT_EQ(saturatingAdd(UINT64_MAX - 1, 5), UINT64_MAX);
}

TEST(MemoryCap, ImagesAreRefusedFromTheirHeader) {
  const auto dir = test::testTempDir("memcap");
  Image image(512, 512, vec4(0.5f, 0.25f, 0.125f, 1.0f));
  const std::string png = (dir / "big.png").string(), exr = (dir / "big.exr").string();
  writePng(png, image);
  writeExr(exr, image);
  {
    CapFor cap(uint64_t(1) << 20);  // 512x512 decodes through 6 to 8 MiB
    expectInputError([&] { readImage(png); },
                     {png, "512x512", "8.0 MiB", "--max-memory", "1.0 MiB"});
    expectInputError([&] { readImage(exr); }, {exr, "512x512", "6.0 MiB", "--max-memory"});
  }
  CapFor cap(uint64_t(16) << 20);
  EXPECT_EQ(readImage(png).width(), 512);
  EXPECT_EQ(readImage(exr).width(), 512);
}

TEST(MemoryCap, MeshesAreRefusedFromTheirHeader) {
  // A million vertices are within LoadLimits::max_vertices but not within 16 MiB; the file holds
  // none of them: the header alone is refused, before anything is read or allocated.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 1000000\nproperty float x\nproperty float y\n"
      "property float z\nelement face 10\nproperty list uchar int vertex_indices\nend_header\n";
  LoadLimits limits;
  limits.max_bytes = uint64_t(16) << 20;
  expectInputError([&] { readPly("claims.ply", ply, limits); },
                   {"claims.ply", "1000000 vertices", "--max-memory", "16 MiB"});
  // The process's cap is what LoadLimits starts from.
  CapFor cap(uint64_t(2) << 20);
  EXPECT_EQ(LoadLimits{}.max_bytes, uint64_t(2) << 20);
  expectInputError([&] { loader::checkLimits("m.obj", "the file", 100000, 10, LoadLimits{}); },
                   {"m.obj", "100000 vertices", "--max-memory"});
  EXPECT_EQ(loader::meshBytes(UINT64_MAX / 2, 1), UINT64_MAX);
}

}  // namespace
}  // namespace mirage
