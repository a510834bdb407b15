// Radiance HDR files: run-length scanlines decode as stb decodes them, and the ones stb cannot
// finish (a run of length 0 loops forever in Debian's stb_image; found by fuzzing) or that run
// past the image are InputErrors naming the file and the scanline — never a hang.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/image.h"

namespace mirage {
namespace {

// A 8x2 image, every channel of every scanline one run: (100, 50, 25) with exponent 130.
std::string rleHdr(unsigned char second_row_count = 128 + 8) {
  std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n";
  for (int row = 0; row < 2; ++row) {
    s += std::string("\x02\x02\x00\x08", 4);
    for (unsigned char value : {100, 50, 25, 130}) {
      s += char(row == 1 && value == 50 ? second_row_count : 128 + 8);
      s += char(value);
    }
  }
  return s;
}

Image decode(const std::string& bytes) {
  return readImageFromMemory("x.hdr", bytes.data(), bytes.size(), Encoding::kLinear);
}

TEST(RadianceCheck, RunLengthScanlinesDecode) {
  const Image img = decode(rleHdr());
  ASSERT_EQ(img.width(), 8);
  ASSERT_EQ(img.height(), 2);
  // RGBE: value / 256 * 2^(130 - 128).
  EXPECT_FLOAT_EQ(img(3, 1).x, 100.0f / 256.0f * 4.0f);
}

TEST(RadianceCheck, MalformedScanlinesAreInputErrorsNotHangs) {
  const struct {
    std::string bytes;
    const char* expected;
  } cases[] = {
      {rleHdr(0), "scanline 1 has a run of length 0"},
      {rleHdr(128 + 9), "scanline 1 runs past its 8 pixels"},
      {rleHdr().substr(0, 65), "ends inside scanline 1 of 2"},
      // Headers stb itself refuses, with its reason.
      {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n-Y 2 +X 8\n", "not a readable image"},
      {"#?RADIANCE\n\n-Y two +X 8\n", "not a readable image"},
  };
  for (const auto& c : cases) {
    try {
      decode(c.bytes);
      ADD_FAILURE() << "no error, expected: " << c.expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << e.what() << " / expected: " << c.expected;
      EXPECT_EQ(std::string(e.what()).rfind("x.hdr", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace mirage
