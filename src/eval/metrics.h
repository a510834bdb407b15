// Image metrics against a reference, over all pixels and over reflector pixels only. Images are
// compared after the display transform (values in [0, 1]), as a viewer would see them.
#pragma once

#include <optional>

#include "core/image.h"

namespace mirage {

// Mean squared error over the RGB channels of the pixels where mask (if given) is non-zero.
double meanSquaredError(const Image& a, const Image& b, const IdImage* mask = nullptr);
// PSNR in dB for a peak of 1; infinite when the images are equal (returned as +inf).
double psnrFromMse(double mse);

// SSIM (Wang et al. 2004) on luma with an 11x11 Gaussian window (sigma 1.5), K1 = 0.01,
// K2 = 0.03, L = 1; returns the per-pixel SSIM map (windows clamped at the borders).
Image2D<float> ssimMap(const Image& a, const Image& b);
// The mean of the map over all pixels, or over masked pixels (mask != 0).
double meanOver(const Image2D<float>& map, const IdImage* mask = nullptr);

struct ImageMetrics {
  double psnr = 0.0, psnr_reflector = 0.0;  // +inf when equal
  double ssim = 0.0, ssim_reflector = 0.0;
  double flip = 0.0, flip_reflector = 0.0;  // mean LDR-FLIP (eval/flip.h), default viewing
  size_t reflector_pixels = 0;
};

// `reflector_mask` marks reflector pixels (the reference's reflector-ID buffer). Where it has no
// reflector pixel, the reflector figures are NaN. `flip_map`, if given, receives the FLIP map the
// FLIP figures are the means of (the report draws it).
ImageMetrics compareImages(const Image& test, const Image& reference, const IdImage& reflector_mask,
                           Image2D<float>* flip_map = nullptr, Image2D<float>* ssim_map = nullptr);

size_t countNonZero(const IdImage& mask);

}  // namespace mirage
