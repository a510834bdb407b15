// LDR-FLIP against values obtained independently of our code.
//
// Where the expected numbers come from: NVIDIA's reference Python implementation of LDR-FLIP
// (NVlabs/flip, python/flip_api.py, compute_ldrflip, v1.1) was transcribed once, outside this
// repository, and run with numpy on the images built below; its cv2.filter2D calls were replaced
// by an edge-replicating 2D correlation (cv2's BORDER_REPLICATE). That implementation filters
// with full 2D kernels, ours with separable passes, so agreement checks the separation too. The
// reference works in float32; over the whole 40x28 pattern below our maps were within 1.5e-5 of
// its maps (FLIP and colour term) and 3.5e-5 (feature term). The constant-colour cases can also
// be checked by hand, as their comments show.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "eval/flip.h"
#include "eval/metrics.h"

namespace mirage {
namespace {

constexpr float kTol = 5e-5f;         // FLIP and colour term
constexpr float kFeatureTol = 2e-4f;  // the feature term is a square root, which magnifies rounding

Image constant(vec3 c, int w = 8, int h = 6) {
  return Image(w, h, vec4(c, 1.0f));
}

// A 40x28 pattern and a copy with a recoloured block (x 10..19, y 8..15: red halved, blue +0.3)
// and one pixel (30, 5) turned white.
void pattern(Image& reference, Image& test) {
  reference = Image(40, 28);
  test = Image(40, 28);
  for (int y = 0; y < 28; ++y)
    for (int x = 0; x < 40; ++x) {
      double r = ((x * 7 + y * 3) % 11) / 10.0, g = ((x / 5 + y / 4) % 2) * 0.8 + 0.1,
             b = ((x * y) % 13) / 12.0;
      reference(x, y) = vec4(float(r), float(g), float(b), 1.0f);
      if (x >= 10 && x < 20 && y >= 8 && y < 16) r *= 0.5, b = std::min(b + 0.3, 1.0);
      if (x == 30 && y == 5) r = g = b = 1.0;
      test(x, y) = vec4(float(r), float(g), float(b), 1.0f);
    }
}

TEST(Flip, DefaultViewingIsAbout67PixelsPerDegree) {
  // 0.7 m * (3840 px / 0.7 m) * pi / 180 = 3840 pi / 180 = 67.0206.
  EXPECT_NEAR(FlipViewing{}.pixelsPerDegree(), 67.0206f, 1e-3f);
  EXPECT_NEAR((FlipViewing{1.0f, 0.5f, 1920.0f}.pixelsPerDegree()), 3840.0f * 3.14159265f / 180.0f,
              1e-2f);
}

TEST(Flip, IdenticalImagesGiveZeroEverywhere) {
  Image a, b;
  pattern(a, b);
  FlipMaps m = flipComponents(b, b);
  for (size_t i = 0; i < m.flip.pixelCount(); ++i) {
    ASSERT_EQ(m.flip.data()[i], 0.0f) << i;
    ASSERT_EQ(m.feature.data()[i], 0.0f) << i;
  }
}

TEST(Flip, ConstantColoursGiveTheMappedHyAbDistance) {
  // Uniform images: the CSF filters keep the colour, the feature detectors see nothing, so
  // FLIP = redistribute(HyAB(Hunt-Lab a, Hunt-Lab b) ^ 0.7). c_max = HyAB(green, blue) ^ 0.7 =
  // 41.2761, p_c c_max = 16.5104.
  struct Case {
    vec3 a, b;
    float expected;
  };
  const Case cases[] = {
      // Black against white: HyAB = 100 (L 0 vs 100, no chroma); 100^0.7 = 25.1189 > 16.5104, so
      // 0.95 + (25.1189 - 16.5104) / (41.2761 - 16.5104) * 0.05 = 0.96738.
      {vec3(0.0f), vec3(1.0f), 0.9673797f},
      // Greys 0.5 and 0.52: linear 0.214041 and 0.233022, L 53.3890 and 55.3823, HyAB 1.99330;
      // 1.99330^0.7 = 1.62069 < 16.5104, so 0.95 / 16.5104 * 1.62069 = 0.093254.
      {vec3(0.5f), vec3(0.52f), 0.0932545f},
      {vec3(1, 0, 0), vec3(0, 1, 0), 0.9866623f},
      {vec3(0.2f, 0.4f, 0.8f), vec3(0.25f, 0.35f, 0.7f), 0.2945946f},
  };
  for (const Case& c : cases) {
    FlipMaps m = flipComponents(constant(c.a), constant(c.b));
    for (size_t i = 0; i < m.flip.pixelCount(); ++i) {
      ASSERT_NEAR(m.flip.data()[i], c.expected, kTol) << i;
      ASSERT_NEAR(m.color.data()[i], c.expected, kTol) << i;
      ASSERT_LT(m.feature.data()[i], 0.01f) << i;
    }
  }
}

TEST(Flip, MatchesTheReferenceImplementationOnAPattern) {
  Image reference, test;
  pattern(reference, test);
  FlipMaps m = flipComponents(test, reference);
  struct Pixel {
    int x, y;
    float flip, color, feature;
  };
  const Pixel pixels[] = {
      {0, 0, 0.0000368f, 0.0000368f, 0.0f},  // ten pixels from the block: the CSF reaches it
      {39, 27, 0.0f, 0.0f, 0.0f},
      {15, 12, 0.5514916f, 0.4908475f, 0.1637007f},  // inside the block
      {10, 8, 0.3283781f, 0.2736226f, 0.1407523f},   // its corner
      {30, 5, 0.3108730f, 0.2646939f, 0.1209846f},   // the white pixel
      {25, 20, 0.0070790f, 0.0064075f, 0.0197343f},
      {5, 25, 0.0004447f, 0.0004447f, 0.0f},
      {21, 17, 0.1428766f, 0.1175587f, 0.0911073f},
  };
  for (const Pixel& p : pixels) {
    EXPECT_NEAR(m.flip(p.x, p.y), p.flip, kTol) << p.x << "," << p.y;
    EXPECT_NEAR(m.color(p.x, p.y), p.color, kTol) << p.x << "," << p.y;
    EXPECT_NEAR(m.feature(p.x, p.y), p.feature, kFeatureTol) << p.x << "," << p.y;
  }
  EXPECT_NEAR(meanOver(m.flip), 0.0756243, 1e-4);
  float max = *std::max_element(m.flip.pixels().begin(), m.flip.pixels().end());
  EXPECT_NEAR(max, 0.5788577f, kTol);
}

TEST(Flip, StepAgainstRampDiffersOnlyNearTheEdge) {
  // Grey 0.2 | 0.8 with a sharp step at x = 32 against a linear ramp over x = 28..35. The
  // images differ in columns 28..35 only; with filter radii of 10 (CSF) and 9 (features) at
  // 67 ppd, columns < 18 and > 45 see identical inputs and must be exactly 0.
  const int w = 64, h = 16;
  Image step(w, h), ramp(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      step(x, y) = vec4(vec3(x < 32 ? 0.2f : 0.8f), 1.0f);
      double t = std::clamp((x - 27.5) / 8.0, 0.0, 1.0);
      ramp(x, y) = vec4(vec3(float(0.2 + 0.6 * t)), 1.0f);
    }
  FlipMaps m = flipComponents(ramp, step);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x < 18 || x > 45) {
        ASSERT_EQ(m.flip(x, y), 0.0f) << x << "," << y;
        ASSERT_EQ(m.feature(x, y), 0.0f) << x << "," << y;
      }
      ASSERT_NEAR(m.flip(x, y), m.flip(x, 0), 1e-5f) << "rows differ at " << x << "," << y;
    }
  // Reference values in the middle row.
  EXPECT_NEAR(m.flip(24, 8), 0.0010361f, kTol);
  EXPECT_NEAR(m.flip(31, 8), 0.2307803f, kTol);
  EXPECT_NEAR(m.flip(32, 8), 0.4913343f, kTol);
  EXPECT_NEAR(m.feature(31, 8), 0.3507561f, kFeatureTol);
  EXPECT_NEAR(m.feature(32, 8), 0.3072119f, kFeatureTol);
  EXPECT_NEAR(meanOver(m.flip), 0.0592470, 1e-4);
  // The edge term raises FLIP above the colour term alone where the edge is.
  EXPECT_GT(m.flip(32, 8), m.color(32, 8) + 0.1f);
}

TEST(Flip, IsSymmetricAndInTheUnitInterval) {
  // Pseudo-random noise against other noise: the most extreme input we can give it.
  Image a(37, 23), b(37, 23);
  uint32_t s = 12345;
  auto next = [&s] { return float((s = s * 1664525u + 1013904223u) >> 8) / float(1 << 24); };
  for (vec4& p : a.pixels()) p = vec4(next(), next(), next(), 1);
  for (vec4& p : b.pixels()) p = vec4(next(), next(), next(), 1);
  Image2D<float> ab = flipMap(a, b), ba = flipMap(b, a);
  for (size_t i = 0; i < ab.pixelCount(); ++i) {
    ASSERT_EQ(ab.data()[i], ba.data()[i]) << i;
    ASSERT_GE(ab.data()[i], 0.0f) << i;
    ASSERT_LE(ab.data()[i], 1.0f) << i;
  }
  EXPECT_GT(meanOver(ab), 0.3);
}

TEST(Flip, FineDetailMattersMoreWhenSeenFromCloser) {
  // A one-pixel checker against a flat grey: up close (few pixels per degree) the checker is
  // seen, from further away the CSF averages it and the colour term falls. (It does not fall to
  // 0: the checker's mean in linear light is not grey 0.5. Reference means of the colour term:
  // 0.4703, 0.2523, 0.1700 at 10, 30, 67 ppd; FLIP 0.7110, 0.2583, 0.1810.)
  Image checker(32, 32), grey(32, 32, vec4(vec3(0.5f), 1));
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) checker(x, y) = vec4(vec3((x + y) % 2 ? 0.3f : 0.7f), 1);
  const float ppd[] = {10.0f, 30.0f, FlipViewing{}.pixelsPerDegree()};
  const double color[] = {0.4702592, 0.2522931, 0.1700284},
               flip[] = {0.7109598, 0.2583319, 0.1810159};
  for (int i = 0; i < 3; ++i) {
    FlipMaps m = flipComponents(checker, grey, ppd[i]);
    EXPECT_NEAR(meanOver(m.color), color[i], 1e-4) << ppd[i];
    EXPECT_NEAR(meanOver(m.flip), flip[i], 1e-4) << ppd[i];
  }
}

TEST(Flip, RejectsMismatchedSizesAndBadViewing) {
  EXPECT_ANY_THROW(flipMap(Image(4, 4), Image(4, 5)));
  EXPECT_ANY_THROW(flipMap(Image(4, 4), Image(4, 4), 0.0f));
  EXPECT_EQ(flipMap(Image(0, 0), Image(0, 0)).pixelCount(), 0u);
}

TEST(Flip, CompareImagesReportsTheMeanOverAllAndOverReflectorPixels) {
  Image reference, test;
  pattern(reference, test);
  IdImage mask(40, 28, 0);
  for (int y = 8; y < 16; ++y)
    for (int x = 10; x < 20; ++x) mask(x, y) = 1;
  Image2D<float> map;
  ImageMetrics m = compareImages(test, reference, mask, &map);
  ASSERT_EQ(map.size(), reference.size());
  EXPECT_NEAR(m.flip, 0.0756243, 1e-4);
  EXPECT_DOUBLE_EQ(m.flip, meanOver(map));
  EXPECT_DOUBLE_EQ(m.flip_reflector, meanOver(map, &mask));
  EXPECT_GT(m.flip_reflector, 0.3);  // the recoloured block is what the mask selects
  ImageMetrics same = compareImages(reference, reference, mask);
  EXPECT_EQ(same.flip, 0.0);
  EXPECT_EQ(same.flip_reflector, 0.0);
  EXPECT_TRUE(std::isnan(compareImages(test, reference, IdImage(40, 28, 0)).flip_reflector));
}

}  // namespace
}  // namespace mirage
