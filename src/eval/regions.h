// Metrics over regions of an image: each reflector's pixels, the pixels of each error cause
// (eval/causes.h). The same figures as the whole-image ones, restricted to a region.
#pragma once

#include <cstddef>
#include <map>

#include "core/image.h"

namespace mirage {

struct RegionMetrics {
  size_t pixels = 0;
  // The sum over the region's pixels of the squared display-value differences of R, G and B:
  // regions' sse add up to the sse of their union (3 * pixels * MSE).
  double sse = 0.0;
  double psnr = 0.0;  // from sse / (3 * pixels), as meanSquaredError; +inf when equal
  double ssim = 0.0;  // the mean of the SSIM map over the region
  double flip = 0.0;  // the mean of the FLIP map over the region
};

// The metrics of every region `labels` marks (label 0: no region), from the two display images
// and the per-pixel SSIM and FLIP maps of the whole comparison (eval/metrics.h's compareImages).
std::map<uint32_t, RegionMetrics> regionMetrics(const Image& test, const Image& reference,
                                                const Image2D<float>& ssim,
                                                const Image2D<float>& flip, const IdImage& labels);

// The figures of a region from accumulated sums (used to merge regions and frames).
void finishRegion(RegionMetrics& r, double ssim_sum, double flip_sum);

}  // namespace mirage
