#include "eval/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/error.h"
#include "eval/flip.h"

namespace mirage {

namespace {

void checkSameSize(const Image& a, const Image& b) {
  if (a.size() != b.size())
    throwRuntime("cannot compare a {}x{} image with a {}x{} one", a.width(), a.height(), b.width(),
                 b.height());
}

float luma(const vec4& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Separable Gaussian blur with clamped borders.
Image2D<float> blur(const Image2D<float>& in, const std::vector<float>& kernel) {
  int r = int(kernel.size() / 2), w = in.width(), h = in.height();
  Image2D<float> tmp(w, h), out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k) s += kernel[size_t(k + r)] * in(std::clamp(x + k, 0, w - 1), y);
      tmp(x, y) = float(s);
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int k = -r; k <= r; ++k)
        s += kernel[size_t(k + r)] * tmp(x, std::clamp(y + k, 0, h - 1));
      out(x, y) = float(s);
    }
  return out;
}

}  // namespace

double meanSquaredError(const Image& a, const Image& b, const IdImage* mask) {
  checkSameSize(a, b);
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    if (mask && mask->data()[i] == 0) continue;
    vec3 d = vec3(a.data()[i]) - vec3(b.data()[i]);
    sum += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    ++n;
  }
  return n ? sum / (3.0 * double(n)) : std::numeric_limits<double>::quiet_NaN();
}

double psnrFromMse(double mse) {
  if (std::isnan(mse)) return mse;
  if (mse <= 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(1.0 / mse);
}

Image2D<float> ssimMap(const Image& a, const Image& b) {
  checkSameSize(a, b);
  const int w = a.width(), h = a.height();
  std::vector<float> kernel(11);
  double total = 0.0;
  for (int i = 0; i < 11; ++i) {
    double x = i - 5;
    kernel[size_t(i)] = float(std::exp(-x * x / (2.0 * 1.5 * 1.5)));
    total += kernel[size_t(i)];
  }
  for (float& k : kernel) k = float(k / total);
  Image2D<float> x(w, h), y(w, h), xx(w, h), yy(w, h), xy(w, h);
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    float p = luma(a.data()[i]), q = luma(b.data()[i]);
    x.data()[i] = p;
    y.data()[i] = q;
    xx.data()[i] = p * p;
    yy.data()[i] = q * q;
    xy.data()[i] = p * q;
  }
  Image2D<float> mx = blur(x, kernel), my = blur(y, kernel), sxx = blur(xx, kernel),
                 syy = blur(yy, kernel), sxy = blur(xy, kernel);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  Image2D<float> map(w, h);
  for (size_t i = 0; i < map.pixelCount(); ++i) {
    double ux = mx.data()[i], uy = my.data()[i];
    double vx = sxx.data()[i] - ux * ux, vy = syy.data()[i] - uy * uy,
           cxy = sxy.data()[i] - ux * uy;
    map.data()[i] =
        float(((2 * ux * uy + c1) * (2 * cxy + c2)) / ((ux * ux + uy * uy + c1) * (vx + vy + c2)));
  }
  return map;
}

double meanOver(const Image2D<float>& map, const IdImage* mask) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < map.pixelCount(); ++i) {
    if (mask && mask->data()[i] == 0) continue;
    sum += map.data()[i];
    ++n;
  }
  return n ? sum / double(n) : std::numeric_limits<double>::quiet_NaN();
}

size_t countNonZero(const IdImage& mask) {
  size_t n = 0;
  for (uint32_t v : mask.pixels()) n += v != 0;
  return n;
}

ImageMetrics compareImages(const Image& test, const Image& reference, const IdImage& mask,
                           Image2D<float>* flip_map, Image2D<float>* ssim_map) {
  ImageMetrics m;
  m.psnr = psnrFromMse(meanSquaredError(test, reference));
  m.psnr_reflector = psnrFromMse(meanSquaredError(test, reference, &mask));
  Image2D<float> map = ssimMap(test, reference);
  m.ssim = meanOver(map);
  m.ssim_reflector = meanOver(map, &mask);
  Image2D<float> flip = flipMap(test, reference);
  m.flip = meanOver(flip);
  m.flip_reflector = meanOver(flip, &mask);
  if (flip_map) *flip_map = std::move(flip);
  m.reflector_pixels = countNonZero(mask);
  if (ssim_map) *ssim_map = std::move(map);
  return m;
}

}  // namespace mirage
