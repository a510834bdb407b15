// A method's frame and the ray tracer's frame of the same view at the same order, both
// display-encoded, with both ID buffers: what the image tests compare. With ssaa > 1 both are
// rendered at ssaa x ssaa sub-pixels per pixel and reduced as `mirage compare --ssaa` does
// (matched sampling: what remains is the method's own error, not aliasing).
#pragma once

#include <map>
#include <string>

#include "core/image.h"
#include "methods/frame.h"

namespace mirage::test {

struct RenderPair {
  Image gpu, cpu;
  IdImage gpu_ids, cpu_ids;
  std::map<std::string, double> stats;  // the method's, after its frame
};

RenderPair renderWithTruth(const Scene& scene, const std::string& method, ivec2 size,
                           const FrameSettings& settings,
                           const std::map<std::string, std::string>& params = {}, float time = 0.0f,
                           int ssaa = 1);

// The supersampling of image tests that assert a method's closeness to the ray tracer: matched
// 2 x 2 (both sides at the same sub-pixel positions; a quarter of compare's 4 x 4 cost), so that
// their thresholds bound the method's error, not aliasing.
inline constexpr int kMatchedSsaa = 2;

// PSNR of the method's frame against the ray tracer's on the ray tracer's reflector pixels.
double reflectorPsnr(const RenderPair& p);

// A rendered frame's colour as the image tests compare it (exposure 1, ACES, sRGB).
Image displayed(const Image& linear);

}  // namespace mirage::test
