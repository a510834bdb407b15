#include "eval/causes.h"

#include <gtest/gtest.h>

#include "eval/metrics.h"
#include "eval/regions.h"

namespace mirage {
namespace {

const uint32_t kEnv = encodeFirstHit(FirstHit::kEnvironment, -1);
const uint32_t kFloor = encodeFirstHit(FirstHit::kDiffuse, 3);
const uint32_t kBox = encodeFirstHit(FirstHit::kDiffuse, 4);
const uint32_t kSelf = encodeFirstHit(FirstHit::kSelf, 1);

TEST(FirstHitCode, PacksTheKindAndTheInstance) {
  EXPECT_EQ(firstHitKind(kFloor), FirstHit::kDiffuse);
  EXPECT_EQ(firstHitInstance(kFloor), 3);
  EXPECT_EQ(firstHitInstance(kEnv), -1);
  EXPECT_NE(kFloor, kBox);  // two objects of one kind are different things
}

TEST(Causes, OnePixelPerSampleTakesItsOwnCode) {
  IdImage hits(3, 1);
  hits(0, 0) = kEnv, hits(1, 0) = kFloor, hits(2, 0) = 0;
  IdImage mask(3, 1, 1u);
  mask(2, 0) = 0;
  PixelCauses c = classifyCauses(hits, 1, mask);
  EXPECT_EQ(c.label(0, 0), uint32_t(FirstHit::kEnvironment));
  EXPECT_EQ(c.label(1, 0), uint32_t(FirstHit::kDiffuse));
  EXPECT_EQ(c.code(1, 0), kFloor);
  EXPECT_EQ(c.label(2, 0), 0u);  // not a reflector pixel: no cause
  EXPECT_EQ(c.mixed(0, 0) + c.mixed(1, 0), 0u);
}

TEST(Causes, SupersampledPixelsTakeTheMajorityOfTheirReflectorSubPixels) {
  IdImage hits(4, 2);  // two output pixels of 2 x 2
  hits(0, 0) = kFloor, hits(1, 0) = kFloor, hits(0, 1) = kBox, hits(1, 1) = 0;
  hits(2, 0) = kSelf, hits(3, 0) = kSelf, hits(2, 1) = kSelf, hits(3, 1) = kSelf;
  IdImage mask(2, 1, 1u);
  PixelCauses c = classifyCauses(hits, 2, mask);
  EXPECT_EQ(c.code(0, 0), kFloor);  // two floor, one box, one off the reflector
  EXPECT_EQ(c.mixed(0, 0), 1u);
  EXPECT_EQ(c.label(1, 0), uint32_t(FirstHit::kSelf));
  EXPECT_EQ(c.mixed(1, 0), 0u);
}

TEST(Causes, AReferencePixelTheRayTracerSeesOffTheReflectorIsUnclassified) {
  IdImage hits(2, 2, 0u);
  IdImage mask(1, 1, 1u);
  EXPECT_EQ(classifyCauses(hits, 2, mask).label(0, 0), kUnclassified);
  EXPECT_THROW(classifyCauses(hits, 4, mask), RuntimeError);  // hits too small for 4 x 4
}

// The sums the report relies on: the regions' pixels and squared errors add up to those of the
// reflector pixels as a whole, and each region's PSNR is that of its own pixels.
TEST(Regions, PixelsAndSquaredErrorsAddUpToTheReflectorTotals) {
  const int w = 16, h = 8;
  Image a(w, h), b(w, h);
  IdImage mask(w, h), labels(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      a(x, y) = vec4(float(x) / w, float(y) / h, 0.5f, 1.0f);
      b(x, y) = vec4(float(x * x % 7) / 7.0f, float(y) / h, 0.25f, 1.0f);
      mask(x, y) = (x + y) % 3 != 0 ? 1u : 0u;
      labels(x, y) = mask(x, y) ? uint32_t(1 + (x * 5 + y) % 4) : 0u;
    }
  Image2D<float> flip, ssim;
  ImageMetrics whole = compareImages(a, b, mask, &flip, &ssim);
  auto regions = regionMetrics(a, b, ssim, flip, labels);
  ASSERT_EQ(regions.size(), 4u);
  size_t pixels = 0;
  double sse = 0.0;
  for (const auto& [label, r] : regions) {
    pixels += r.pixels;
    sse += r.sse;
    IdImage only(w, h);
    for (size_t i = 0; i < only.pixelCount(); ++i)
      only.data()[i] = labels.data()[i] == label ? 1u : 0u;
    EXPECT_NEAR(r.psnr, psnrFromMse(meanSquaredError(a, b, &only)), 1e-9) << label;
    EXPECT_NEAR(r.ssim, meanOver(ssim, &only), 1e-9) << label;
  }
  EXPECT_EQ(pixels, whole.reflector_pixels);
  EXPECT_NEAR(sse, 3.0 * double(whole.reflector_pixels) * meanSquaredError(a, b, &mask), 1e-9);
}

}  // namespace
}  // namespace mirage
