// LDR-FLIP. The paper's 2D filters are applied as sums of separable 1D passes; this is exact, not
// an approximation: a Gaussian in r^2 = x^2 + y^2 factors into x and y, and the blue-yellow CSF,
// a sum of two Gaussians, is the sum of two such products. The edge and point detectors are a
// Gaussian derivative in one axis times a Gaussian in the other, normalised per axis, which gives
// the same weights as the reference's 2D normalisation (positive and negative weights summing to
// +1 and -1), because the sign of each weight depends on one axis only.
#include "eval/flip.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace mirage {

namespace {

// Exponents and error redistribution (paper section 4): colour distances are raised to q_c and
// mapped linearly so that p_c * c_max lands on p_t, compressing the largest errors into
// (p_t, 1]; feature differences are raised to q_f.
constexpr float kQc = 0.7f, kQf = 0.5f, kPc = 0.4f, kPt = 0.95f;
// Peak-to-trough width, in degrees, of the human edge detector (two standard deviations).
constexpr float kEdgeWidthDeg = 0.082f;

// Contrast sensitivity of a YCxCz channel in the paper's form, r in degrees:
// a1 sqrt(pi / b1) exp(-pi^2 r^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 r^2 / b2).
// Achromatic and red-green are single Gaussians (a2 = 0).
struct Csf {
  float a1, b1, a2, b2;
};
constexpr Csf kCsfY{1.0f, 0.0047f, 0.0f, 1e-5f};
constexpr Csf kCsfCx{1.0f, 0.0053f, 0.0f, 1e-5f};
constexpr Csf kCsfCz{34.1f, 0.04f, 13.5f, 0.025f};
// The widest Gaussian (largest b) sets one radius for all three filters, as in the reference.
constexpr float kMaxCsfScale = 0.04f;

// D65 white point (XYZ) and its inverse, to the reference's digits.
const vec3 kWhite(0.950428545f, 1.0f, 1.088900371f);
const vec3 kInvWhite(1.052156925f, 1.0f, 0.918357670f);

vec3 linearRgbToXyz(vec3 c) {
  // sRGB primaries with D65, as exact ratios.
  return {(10135552.0f / 24577794.0f) * c.x + (8788810.0f / 24577794.0f) * c.y +
              (4435075.0f / 24577794.0f) * c.z,
          (2613072.0f / 12288897.0f) * c.x + (8788810.0f / 12288897.0f) * c.y +
              (887015.0f / 12288897.0f) * c.z,
          (1425312.0f / 73733382.0f) * c.x + (8788810.0f / 73733382.0f) * c.y +
              (70074185.0f / 73733382.0f) * c.z};
}

vec3 xyzToLinearRgb(vec3 c) {
  return {3.241003275f * c.x - 1.537398934f * c.y - 0.498615861f * c.z,
          -0.969224334f * c.x + 1.875930071f * c.y + 0.041554224f * c.z,
          0.055639423f * c.x - 0.204011202f * c.y + 1.057148933f * c.z};
}

// YCxCz: CIELab without the cube root, a linear opponent space where spatial filtering is valid.
vec3 xyzToYCxCz(vec3 xyz) {
  vec3 v = xyz * kInvWhite;
  return {116.0f * v.y - 16.0f, 500.0f * (v.x - v.y), 200.0f * (v.y - v.z)};
}

vec3 yCxCzToXyz(vec3 c) {
  float y = (c.x + 16.0f) / 116.0f;
  return vec3(y + c.y / 500.0f, y, y - c.z / 200.0f) * kWhite;
}

float labF(float t) {
  constexpr float kDelta = 6.0f / 29.0f;
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0f * kDelta * kDelta) + 4.0f / 29.0f;
}

// CIELab with the Hunt effect: chroma scales with lightness (0.01 L), so that dark colours
// differ less in hue than bright ones, as observed.
vec3 huntLab(vec3 linear_rgb) {
  vec3 v = linearRgbToXyz(linear_rgb) * kInvWhite;
  float fx = labF(v.x), fy = labF(v.y), fz = labF(v.z);
  float l = 116.0f * fy - 16.0f;
  return {l, 0.01f * l * 500.0f * (fx - fy), 0.01f * l * 200.0f * (fy - fz)};
}

// HyAB: city-block distance in lightness plus Euclidean distance in chroma, which matches
// large colour differences better than Euclidean Lab distance.
float hyab(vec3 a, vec3 b) {
  vec2 ab(a.y - b.y, a.z - b.z);
  return std::abs(a.x - b.x) + std::sqrt(glm::dot(ab, ab));
}

using Kernel = std::vector<float>;
using Plane = std::vector<float>;

// A 2D CSF filter as a sum of separable terms k_i(x) k_i(y), normalised to sum to 1.
std::vector<Kernel> csfFilter(const Csf& csf, float ppd, int radius) {
  std::vector<Kernel> terms;
  double total = 0.0;
  for (auto [a, b] : {std::pair(csf.a1, csf.b1), std::pair(csf.a2, csf.b2)}) {
    if (a == 0.0f) continue;
    Kernel k(size_t(2 * radius + 1));
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
      float x = float(i) / ppd;
      // sqrt of the amplitude: the product of the x and y factors carries it once.
      k[size_t(i + radius)] = std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x * x / b);
      sum += k[size_t(i + radius)];
    }
    total += sum * sum;  // the 2D term sums to the square of its 1D sum
    terms.push_back(std::move(k));
  }
  for (Kernel& k : terms)
    for (float& w : k) w = float(w / std::sqrt(total));
  return terms;
}

struct FeatureKernels {
  Kernel gauss, edge, point;  // Gaussian, its first and second derivative
};

FeatureKernels featureKernels(float ppd) {
  const float sd = 0.5f * kEdgeWidthDeg * ppd;
  const int radius = int(std::ceil(3.0f * sd));
  FeatureKernels f;
  for (Kernel* k : {&f.gauss, &f.edge, &f.point}) k->resize(size_t(2 * radius + 1));
  double g_sum = 0.0, e_pos = 0.0, e_neg = 0.0, p_pos = 0.0, p_neg = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    float x = float(i), g = std::exp(-x * x / (2.0f * sd * sd));
    float e = -x * g, p = (x * x / (sd * sd) - 1.0f) * g;
    size_t j = size_t(i + radius);
    f.gauss[j] = g, f.edge[j] = e, f.point[j] = p;
    g_sum += g;
    (e > 0.0f ? e_pos : e_neg) += std::abs(e);
    (p > 0.0f ? p_pos : p_neg) += std::abs(p);
  }
  // The Gaussian sums to 1; positive and negative derivative weights to +1 and -1, so that a
  // unit step or a unit point gives a response of 1.
  for (size_t j = 0; j < f.gauss.size(); ++j) {
    f.gauss[j] = float(f.gauss[j] / g_sum);
    f.edge[j] = float(f.edge[j] / (f.edge[j] > 0.0f ? e_pos : e_neg));
    f.point[j] = float(f.point[j] / (f.point[j] > 0.0f ? p_pos : p_neg));
  }
  return f;
}

// One separable pass along rows (horizontal) or columns (vertical), borders clamped to the edge
// pixel (the reference's border mode).
Plane convolveRows(const Plane& src, int w, int h, const Kernel& k) {
  const int r = int(k.size() / 2);
  Plane dst(src.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> padded(size_t(w + 2 * r));
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const float* in = &src[size_t(y) * size_t(w)];
      for (int x = -r; x < w + r; ++x) padded[size_t(x + r)] = in[std::clamp(x, 0, w - 1)];
      float* out = &dst[size_t(y) * size_t(w)];
      std::fill(out, out + w, 0.0f);
      for (int j = 0; j <= 2 * r; ++j) {
        const float kj = k[size_t(j)];
        const float* p = &padded[size_t(j)];
        for (int x = 0; x < w; ++x) out[x] += kj * p[x];
      }
    }
  });
  return dst;
}

Plane convolveColumns(const Plane& src, int w, int h, const Kernel& k) {
  const int r = int(k.size() / 2);
  Plane dst(src.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      float* out = &dst[size_t(y) * size_t(w)];
      std::fill(out, out + w, 0.0f);
      for (int j = -r; j <= r; ++j) {
        const float kj = k[size_t(j + r)];
        const float* in = &src[size_t(std::clamp(y + j, 0, h - 1)) * size_t(w)];
        for (int x = 0; x < w; ++x) out[x] += kj * in[x];
      }
    }
  });
  return dst;
}

Plane convolve(const Plane& src, int w, int h, const Kernel& kx, const Kernel& ky) {
  return convolveColumns(convolveRows(src, w, h, kx), w, h, ky);
}

void parallelPixels(size_t n, const auto& body) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) body(i);
  });
}

// What FLIP needs of one image: its CSF-filtered colour (Hunt-adjusted Lab) and the magnitudes
// of its edge and point responses.
struct Perceived {
  std::vector<vec3> lab;
  Plane edges, points;
};

Perceived perceive(const Image& image, const std::vector<Kernel> (&csf)[3],
                   const FeatureKernels& fk) {
  const int w = image.width(), h = image.height();
  const size_t n = image.pixelCount();
  Plane channel[3];
  for (Plane& c : channel) c.resize(n);
  parallelPixels(n, [&](size_t i) {
    vec3 srgb = glm::clamp(vec3(image.data()[i]), 0.0f, 1.0f);
    vec3 lin(srgbToLinear(srgb.x), srgbToLinear(srgb.y), srgbToLinear(srgb.z));
    vec3 ycc = xyzToYCxCz(linearRgbToXyz(lin));
    for (int c = 0; c < 3; ++c) channel[c][i] = ycc[c];
  });

  // Colour: CSF filtering per channel, then back to linear RGB, clamped to the displayable cube.
  Plane filtered[3];
  for (int c = 0; c < 3; ++c) {
    filtered[c].assign(n, 0.0f);
    for (const Kernel& k : csf[c]) {
      Plane term = convolve(channel[c], w, h, k, k);
      for (size_t i = 0; i < n; ++i) filtered[c][i] += term[i];
    }
  }
  Perceived p;
  p.lab.resize(n);
  parallelPixels(n, [&](size_t i) {
    vec3 xyz = yCxCzToXyz(vec3(filtered[0][i], filtered[1][i], filtered[2][i]));
    p.lab[i] = huntLab(glm::clamp(xyzToLinearRgb(xyz), 0.0f, 1.0f));
  });

  // Features on the achromatic channel normalised to [0, 1].
  Plane gray(n);
  for (size_t i = 0; i < n; ++i) gray[i] = channel[0][i] * (1.0f / 116.0f) + 16.0f / 116.0f;
  Plane smooth_x = convolveRows(gray, w, h, fk.gauss);
  Plane dx = convolveColumns(convolveRows(gray, w, h, fk.edge), w, h, fk.gauss);
  Plane ddx = convolveColumns(convolveRows(gray, w, h, fk.point), w, h, fk.gauss);
  Plane dy = convolveColumns(smooth_x, w, h, fk.edge);
  Plane ddy = convolveColumns(smooth_x, w, h, fk.point);
  p.edges.resize(n);
  p.points.resize(n);
  for (size_t i = 0; i < n; ++i) {
    p.edges[i] = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
    p.points[i] = std::sqrt(ddx[i] * ddx[i] + ddy[i] * ddy[i]);
  }
  return p;
}

}  // namespace

float FlipViewing::pixelsPerDegree() const {
  return distance_m * (screen_width_px / screen_width_m) * (kPi / 180.0f);
}

FlipMaps flipComponents(const Image& test, const Image& reference, float ppd) {
  if (test.size() != reference.size())
    throwRuntime("FLIP: cannot compare a {}x{} image with a {}x{} one", test.width(), test.height(),
                 reference.width(), reference.height());
  if (!(ppd > 0.0f) || !std::isfinite(ppd))
    throwRuntime("FLIP: pixels per degree must be > 0, got {}", ppd);
  const int w = test.width(), h = test.height();
  FlipMaps maps{Image2D<float>(w, h), Image2D<float>(w, h), Image2D<float>(w, h)};
  if (test.empty()) return maps;

  const int csf_radius = int(std::ceil(3.0f * std::sqrt(kMaxCsfScale / (2.0f * kPi * kPi)) * ppd));
  const std::vector<Kernel> csf[3] = {csfFilter(kCsfY, ppd, csf_radius),
                                      csfFilter(kCsfCx, ppd, csf_radius),
                                      csfFilter(kCsfCz, ppd, csf_radius)};
  const FeatureKernels fk = featureKernels(ppd);
  const Perceived a = perceive(test, csf, fk), b = perceive(reference, csf, fk);

  // c_max: the largest distance between two displayable colours, green against blue.
  const float cmax = std::pow(hyab(huntLab(vec3(0, 1, 0)), huntLab(vec3(0, 0, 1))), kQc);
  const float pccmax = kPc * cmax;
  parallelPixels(test.pixelCount(), [&](size_t i) {
    float c = std::pow(hyab(a.lab[i], b.lab[i]), kQc);
    c = c < pccmax ? c * (kPt / pccmax) : kPt + (c - pccmax) / (cmax - pccmax) * (1.0f - kPt);
    float diff = std::max(std::abs(a.edges[i] - b.edges[i]), std::abs(a.points[i] - b.points[i]));
    // Responses to [0, 1] input are at most sqrt 2, so f <= 1 but for rounding.
    float f = std::min(std::pow(diff / std::numbers::sqrt2_v<float>, kQf), 1.0f);
    maps.color.data()[i] = c;
    maps.feature.data()[i] = f;
    maps.flip.data()[i] = std::pow(c, 1.0f - f);
  });
  return maps;
}

Image2D<float> flipMap(const Image& test, const Image& reference, float ppd) {
  return flipComponents(test, reference, ppd).flip;
}

}  // namespace mirage
