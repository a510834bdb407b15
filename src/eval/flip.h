// LDR-FLIP (Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020):
// the perceived difference between two display images when a viewer flips between them, per
// pixel, in [0, 1]. We use it beside PSNR/SSIM because it weighs errors the way a viewer sees
// them at a given viewing distance: contrast-sensitivity filtering in an opponent colour space,
// a perceptually uniform colour distance (Hunt-adjusted HyAB) and a separate penalty for edges
// and points that appear, vanish or move. Constants and pipeline follow the paper and NVIDIA's
// reference implementation (NVlabs/flip, v1.2+ separable filters), which our tests reproduce.
#pragma once

#include "core/image.h"

namespace mirage {

// How the images are watched. The default is the paper's: a 0.7 m wide 3840-pixel monitor seen
// from 0.7 m, about 67 pixels per degree of visual angle.
struct FlipViewing {
  float distance_m = 0.7f;
  float screen_width_m = 0.7f;
  float screen_width_px = 3840.0f;

  // Pixels per degree of visual angle, as the reference defines it (small-angle form).
  float pixelsPerDegree() const;
};

// The maps FLIP combines: `flip` = color ^ (1 - feature), each in [0, 1].
struct FlipMaps {
  Image2D<float> flip;
  Image2D<float> color;    // redistributed Hunt-adjusted HyAB distance after CSF filtering
  Image2D<float> feature;  // edge/point difference, ((max diff) / sqrt 2) ^ q_f
};

// `test` and `reference` are display-encoded sRGB images (mirage's toDisplay output); RGB values
// are clamped to [0, 1], alpha is ignored. FLIP is symmetric in its two images.
FlipMaps flipComponents(const Image& test, const Image& reference,
                        float pixels_per_degree = FlipViewing{}.pixelsPerDegree());
Image2D<float> flipMap(const Image& test, const Image& reference,
                       float pixels_per_degree = FlipViewing{}.pixelsPerDegree());

}  // namespace mirage
