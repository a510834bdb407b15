// Matched supersampling (--ssaa N): a frame rendered at N x N times the output's pixels, then
// reduced to the output size. Every method and the ray tracer go through the same reduction, so
// both sides of a comparison are sampled at exactly the same N x N sub-pixel positions (the
// centres of the large frame's pixels: a regular grid) and what remains is the technique's error.
#pragma once

#include <cstdint>
#include <span>

#include "core/image.h"

namespace mirage {

inline constexpr int kMaxSsaa = 8;

// The size rendered for an output of `size` at `ssaa` sub-pixels per side.
inline ivec2 supersampledSize(ivec2 size, int ssaa) {
  return size * ssaa;
}

// The box filter in linear radiance: each output pixel's RGB is the mean of its N x N block.
// Alpha (the distance from the eye) is not averaged, which would invent distances between a
// near and a far surface: it is the block's sample nearest the pixel centre (the rasteriser's
// and the ray tracer's own rule at N = 1). `n` = 1 returns the image unchanged.
Image boxDownsample(const Image& image, int n);

// The id of each N x N block: the most frequent id among its sub-pixels, ties to the smaller id
// (so a pixel half on a reflector and half off counts as the reflector's only when most of it
// is). `n` = 1 returns the image unchanged.
IdImage majorityDownsample(const IdImage& ids, int n);

// The most frequent of `values` (non-empty), ties to the smaller value; sorts them in place. The
// one rule for reflector ids here and for first-hit codes in eval/causes.
uint32_t mostFrequent(std::span<uint32_t> values);

}  // namespace mirage
