// Error attribution by cause: every reflector pixel is classified by what its reflected ray meets
// first in the ray tracer (core/first_hit.h) — the environment, a diffuse object, the reflector
// itself, another reflector, or a reflector past the last allowed bounce — so that a report can
// say where each method loses its decibels. Under --ssaa a pixel's N x N sub-pixels are
// classified one by one and the pixel takes their majority; pixels whose sub-pixels disagree are
// also counted as `mixed`.
#pragma once

#include <string>

#include "core/first_hit.h"
#include "core/image.h"

namespace mirage {

// Cause labels (1-based, 0: not a reflector pixel): FirstHit's kinds 1..5, then kUnclassified
// for a reflector pixel of the reference (a method other than the ray tracer) where no sub-pixel
// of the ray tracer hit a reflector.
inline constexpr uint32_t kUnclassified = 6;
// The name of cause label 1..kUnclassified, as metrics.json spells it.
const char* causeName(uint32_t label);
// The colour the cause image draws a label with (linear [0, 1] display colour).
vec3 causeColour(uint32_t label);

struct PixelCauses {
  IdImage label;  // per output pixel: the cause label, 0 where the mask has no reflector
  IdImage code;   // per output pixel: the majority first-hit code (which object, for diffuse)
  IdImage mixed;  // 1 where a reflector pixel's sub-pixels met different things
};

// `first_hits`: the ray tracer's codes at the supersampled size (n x n per output pixel);
// `mask`: the reference's reflector ids at the output size. Among a pixel's sub-pixels that hit
// a reflector, the most frequent code wins (ties: the smaller code).
PixelCauses classifyCauses(const IdImage& first_hits, int n, const IdImage& mask);

// The classification drawn for the report: each reflector pixel in its cause's colour (mixed
// pixels darker), the rest of the frame as the reference's grey, dimmed.
Image causeImage(const PixelCauses& causes, const Image& reference_display);

}  // namespace mirage
