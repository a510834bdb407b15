#include "core/supersample.h"

#include <vector>

#include <gtest/gtest.h>

namespace mirage {
namespace {

TEST(Supersample, BoxFilterIsTheMeanOfEachBlockAndKeepsTheCentreDistance) {
  Image image(4, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) image(x, y) = vec4(float(x), float(y), float(x * y), 10.0f * x + y);
  Image out = boxDownsample(image, 2);
  ASSERT_EQ(out.size(), ivec2(2, 1));
  // Block (0, 0): x in {0, 1}, y in {0, 1}.
  EXPECT_FLOAT_EQ(out(0, 0).x, 0.5f);
  EXPECT_FLOAT_EQ(out(0, 0).y, 0.5f);
  EXPECT_FLOAT_EQ(out(0, 0).z, 0.25f);  // (0 + 0 + 0 + 1) / 4
  EXPECT_FLOAT_EQ(out(1, 0).x, 2.5f);
  EXPECT_FLOAT_EQ(out(1, 0).z, 1.25f);  // (0 + 0 + 2 + 3) / 4
  // Alpha is not averaged: the sub-pixel at (n/2, n/2) of the block, nearest the centre.
  EXPECT_FLOAT_EQ(out(0, 0).w, 11.0f);
  EXPECT_FLOAT_EQ(out(1, 0).w, 31.0f);
}

TEST(Supersample, FactorOneIsTheIdentity) {
  Image image(3, 2, vec4(0.25f, 0.5f, 0.75f, 7.0f));
  image(1, 1) = vec4(1.0f, 2.0f, 3.0f, 4.0f);
  Image out = boxDownsample(image, 1);
  EXPECT_EQ(out.pixels(), image.pixels());
  IdImage ids(3, 2, 1u);
  ids(2, 0) = 5;
  EXPECT_EQ(majorityDownsample(ids, 1).pixels(), ids.pixels());
}

TEST(Supersample, ConstantRadianceStaysExact) {
  // A block of equal values averages to the same float: flat regions lose nothing.
  Image image(24, 16, vec4(0.3f, 0.7f, 0.1f, 2.0f));
  for (int n : {2, 4, 8}) {
    Image out = boxDownsample(image, n);
    for (const vec4& p : out.pixels()) EXPECT_EQ(p, vec4(0.3f, 0.7f, 0.1f, 2.0f)) << n;
  }
}

TEST(Supersample, IdsTakeTheMajorityWithTiesToTheSmallerId) {
  IdImage ids(4, 4, 0u);
  ids(0, 0) = 2, ids(1, 0) = 2, ids(0, 1) = 2;                 // block (0, 0): three 2s, one 0
  ids(2, 0) = 3, ids(3, 0) = 3;                                // block (1, 0): two 3s, two 0s: tie
  ids(0, 2) = 5, ids(1, 2) = 4, ids(0, 3) = 4, ids(1, 3) = 5;  // two 4s, two 5s
  IdImage out = majorityDownsample(ids, 2);
  EXPECT_EQ(out(0, 0), 2u);
  EXPECT_EQ(out(1, 0), 0u);  // half on the reflector is not a reflector pixel
  EXPECT_EQ(out(0, 1), 4u);
  EXPECT_EQ(out(1, 1), 0u);
}

TEST(Supersample, MostFrequentTakesTheLongestRunWithTiesToTheSmallerValue) {
  std::vector<uint32_t> values = {9, 4, 9, 7, 4, 9};
  EXPECT_EQ(mostFrequent(values), 9u);
  values = {8, 3, 8, 3, 5};
  EXPECT_EQ(mostFrequent(values), 3u);
  values = {42};
  EXPECT_EQ(mostFrequent(values), 42u);
}

TEST(Supersample, RefusesAFactorThatDoesNotDivideTheImage) {
  EXPECT_THROW(boxDownsample(Image(6, 4), 4), RuntimeError);
  EXPECT_THROW(boxDownsample(Image(8, 8), 0), RuntimeError);
  EXPECT_THROW(majorityDownsample(IdImage(18, 18), 9), RuntimeError);
}

}  // namespace
}  // namespace mirage
