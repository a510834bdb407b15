// Metrics against values computed by hand.
#include <gtest/gtest.h>

#include "eval/metrics.h"

namespace mirage {
namespace {

TEST(Metrics, MseAndPsnrByHand) {
  Image a(2, 1, vec4(0.5f, 0.5f, 0.5f, 1)), b(2, 1, vec4(0.5f, 0.5f, 0.5f, 1));
  b(0, 0) = vec4(0.6f, 0.5f, 0.5f, 1);  // one channel of one pixel off by 0.1
  double mse = meanSquaredError(a, b);
  EXPECT_NEAR(mse, 0.01 / 6.0, 1e-9);
  EXPECT_NEAR(psnrFromMse(mse), 10.0 * std::log10(600.0), 1e-4);
  EXPECT_TRUE(std::isinf(psnrFromMse(meanSquaredError(a, a))));
}

TEST(Metrics, MaskSelectsPixels) {
  Image a(2, 1, vec4(0.0f)), b(2, 1, vec4(0.0f));
  b(1, 0) = vec4(1.0f);
  IdImage mask(2, 1, 0);
  mask(0, 0) = 3;
  EXPECT_EQ(meanSquaredError(a, b, &mask), 0.0);
  mask(1, 0) = 1;
  EXPECT_NEAR(meanSquaredError(a, b, &mask), 0.5, 1e-12);
  IdImage none(2, 1, 0);
  EXPECT_TRUE(std::isnan(meanSquaredError(a, b, &none)));
  EXPECT_EQ(countNonZero(mask), 2u);
}

TEST(Metrics, SsimIsOneForEqualImagesAndDropsWithNoise) {
  Image a(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) a(x, y) = vec4(float((x / 4 + y / 4) % 2), 0.3f, 0.6f, 1.0f);
  EXPECT_NEAR(meanOver(ssimMap(a, a)), 1.0, 1e-6);
  Image b = a;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      b(x, y).x = std::clamp(b(x, y).x + ((x * 7 + y * 3) % 5 - 2) * 0.3f, 0.0f, 1.0f);
  double s = meanOver(ssimMap(a, b));
  EXPECT_LT(s, 0.95);
  EXPECT_GT(s, 0.0);
}

TEST(Metrics, SsimOfConstantImagesFollowsTheFormula) {
  // Constant images: variances are 0, so SSIM = (2 mu_x mu_y + C1) / (mu_x^2 + mu_y^2 + C1).
  Image a(16, 16, vec4(0.5f, 0.5f, 0.5f, 1)), b(16, 16, vec4(0.25f, 0.25f, 0.25f, 1));
  const double c1 = 1e-4, x = 0.5, y = 0.25;
  EXPECT_NEAR(meanOver(ssimMap(a, b)), (2 * x * y + c1) / (x * x + y * y + c1), 1e-5);
}

}  // namespace
}  // namespace mirage
