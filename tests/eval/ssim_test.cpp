// SSIM against values obtained independently of our code.
//
// Where the expected numbers come from: scikit-image 0.19.3 (Debian 12's python3-skimage, with
// SciPy 1.10.1 and NumPy 1.24.2), skimage.metrics.structural_similarity(test, reference,
// gaussian_weights=True, sigma=1.5, use_sample_covariance=False, data_range=1.0, full=True): the
// Gaussian-windowed SSIM of Wang et al. (2004) with the paper's constants and a window of 11
// taps (truncate 3.5), as ours: these pin every pixel whose window lies inside the image. At the
// borders scikit-image reflects the image where we clamp to the border pixels, so the border
// values and the means over the whole map come from the same formula over SciPy 1.10.1's
// scipy.ndimage.gaussian_filter(z, 1.5, truncate=3.5, mode='nearest') (with mode='reflect' that
// formula gives scikit-image's full map to the last bit). The images are grey, so our luma is
// the grey level, and hold k / 255 for integer k from the formulas below (exact in float and
// double). tests/eval/ssim_reference.py prints them (Debian's python3 with python3-skimage):
//   W, H = 40, 28; k = (x*37 + y*91 + (x*y) % 53) % 256
//   noisy: min(255, max(0, k + (x*13 + y*7) % 41 - 20)); scrambled: (k*7 + 11) % 256
//   brighter: reference (x*6 + y*3) % 256, test min(255, reference + 30)
// scikit-image's own mean crops 5 pixels at each border (croppedMean below).
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "eval/metrics.h"

namespace mirage {
namespace {

constexpr double kTol = 1e-5;  // our float32 images and sums against float64

Image grey(int w, int h, const std::function<int(int, int)>& level) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = float(level(x, y)) / 255.0f;
      img(x, y) = vec4(v, v, v, 1.0f);
    }
  return img;
}

int pattern(int x, int y) {
  return (x * 37 + y * 91 + (x * y) % 53) % 256;
}

// The mean of the map without `pad` pixels at each border (skimage's mssim, pad 5).
double croppedMean(const Image2D<float>& map, int pad) {
  double sum = 0.0;
  int n = 0;
  for (int y = pad; y < map.height() - pad; ++y)
    for (int x = pad; x < map.width() - pad; ++x, ++n) sum += map(x, y);
  return sum / n;
}

TEST(SsimReference, NoisyPatternMatchesScikitImage) {
  const Image reference = grey(40, 28, pattern);
  const Image test = grey(40, 28, [](int x, int y) {
    return std::clamp(pattern(x, y) + (x * 13 + y * 7) % 41 - 20, 0, 255);
  });
  const Image2D<float> map = ssimMap(test, reference);
  EXPECT_NEAR(map(5, 5), 0.9875531538598039, kTol);
  EXPECT_NEAR(map(12, 9), 0.9881333110666913, kTol);
  EXPECT_NEAR(map(20, 14), 0.986991973203685, kTol);
  EXPECT_NEAR(map(33, 20), 0.9895971664013171, kTol);
  EXPECT_NEAR(map(34, 22), 0.989427916024879, kTol);
  EXPECT_NEAR(croppedMean(map, 5), 0.9877025073083059, kTol);
  // Corners and edges, where the windows run past the image (SciPy, 'nearest').
  EXPECT_NEAR(map(0, 0), 0.9930687948366689, kTol);
  EXPECT_NEAR(map(39, 27), 0.9830647328381092, kTol);
  EXPECT_NEAR(map(20, 0), 0.9882729380880255, kTol);
  EXPECT_NEAR(meanOver(map), 0.9877207950828831, kTol);
}

TEST(SsimReference, ScrambledPatternMatchesScikitImage) {
  const Image reference = grey(40, 28, pattern);
  const Image test = grey(40, 28, [](int x, int y) { return (pattern(x, y) * 7 + 11) % 256; });
  const Image2D<float> map = ssimMap(test, reference);
  EXPECT_NEAR(map(20, 10), 0.11852697235371665, kTol);
  EXPECT_NEAR(croppedMean(map, 5), 0.12059123162144521, kTol);
  EXPECT_NEAR(map(0, 0), 0.4107352331073632, kTol);
  EXPECT_NEAR(map(39, 27), -0.24339433929469284, kTol);
  EXPECT_NEAR(map(20, 0), 0.0750790758707671, kTol);
  EXPECT_NEAR(meanOver(map), 0.14418707900372832, kTol);
}

TEST(SsimReference, BrighterRampMatchesScikitImage) {
  auto ramp = [](int x, int y) { return (x * 6 + y * 3) % 256; };
  const Image reference = grey(40, 28, ramp);
  const Image test = grey(40, 28, [&](int x, int y) { return std::min(255, ramp(x, y) + 30); });
  const Image2D<float> map = ssimMap(test, reference);
  EXPECT_NEAR(map(20, 10), 0.9836084988294692, kTol);
  EXPECT_NEAR(croppedMean(map, 5), 0.9682557234113925, kTol);
  EXPECT_NEAR(map(0, 0), 0.2917607813074925, kTol);
  EXPECT_NEAR(map(39, 27), 0.9093619469155153, kTol);
  EXPECT_NEAR(meanOver(map), 0.9404487435106684, kTol);
}

}  // namespace
}  // namespace mirage
