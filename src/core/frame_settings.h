// The settings of one frame that every method and the ray tracer's comparison share: the
// reflection order, filtered lookups, and matched supersampling's pixel scale. Plain data, in
// core/ so that the commands and the viewer set them without knowing the render passes.
#pragma once

namespace mirage {

// The largest reflection order K any command, the viewer or a method accepts (0 = none).
inline constexpr int kMaxOrder = 16;

struct FrameSettings {
  int order = 2;    // reflection order K, 0..kMaxOrder
  bool mip = true;  // mip-mapped (filtered) reflection lookups
  // Frame pixels per output pixel along each axis (--ssaa N: the frame is rendered N times wider
  // and higher, then box-filtered down). A method's sizes given in output pixels (splats, search
  // radii, steps) are multiplied by it, so that the technique does at N x N what it does at
  // native resolution, only sampled more finely.
  int pixel_scale = 1;
};

}  // namespace mirage
