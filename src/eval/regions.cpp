#include "eval/regions.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "eval/metrics.h"

namespace mirage {

void finishRegion(RegionMetrics& r, double ssim_sum, double flip_sum) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double n = double(r.pixels);
  r.psnr = r.pixels ? psnrFromMse(r.sse / (3.0 * n)) : nan;
  r.ssim = r.pixels ? ssim_sum / n : nan;
  r.flip = r.pixels ? flip_sum / n : nan;
}

std::map<uint32_t, RegionMetrics> regionMetrics(const Image& test, const Image& reference,
                                                const Image2D<float>& ssim,
                                                const Image2D<float>& flip, const IdImage& labels) {
  const ivec2 size = reference.size();
  if (test.size() != size || ssim.size() != size || flip.size() != size || labels.size() != size)
    throwRuntime("regionMetrics: images of different sizes");
  struct Sums {
    RegionMetrics r;
    double ssim = 0.0, flip = 0.0;
  };
  std::map<uint32_t, Sums> sums;
  for (size_t i = 0; i < labels.pixelCount(); ++i) {
    const uint32_t label = labels.data()[i];
    if (label == 0) continue;
    Sums& s = sums[label];
    const vec3 d = vec3(test.data()[i]) - vec3(reference.data()[i]);
    s.r.sse += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    s.ssim += ssim.data()[i];
    s.flip += flip.data()[i];
    ++s.r.pixels;
  }
  std::map<uint32_t, RegionMetrics> out;
  for (auto& [label, s] : sums) {
    finishRegion(s.r, s.ssim, s.flip);
    out[label] = s.r;
  }
  return out;
}

}  // namespace mirage
