// Error heat maps: per-pixel error between two display images, coloured with a perceptually
// uniform map (magma) on a fixed scale so that maps of different methods compare.
#pragma once

#include "core/image.h"

namespace mirage {

// Mean absolute RGB difference per pixel.
Image2D<float> absoluteError(const Image& a, const Image& b);
// Colours `error` (0 -> black ... max_error and above -> pale yellow).
Image heatmap(const Image2D<float>& error, float max_error);
// The colour of a value in [0, 1] on the magma map.
vec3 magma(float t);

}  // namespace mirage
