// Method `ssr`: the hierarchical-Z pyramid of a depth buffer — a mip chain of each cell's
// nearest depth (r) and the behind limit of its farthest drawn depth (g, ssr_depth_shared.h), so
// that a reflected ray's march can skip a whole 2^l x 2^l cell whose nearest depth it stays in
// front of, or whose surfaces it passes behind beyond the thickness (ssr_march_shared.h). The
// pyramid is a power of two a side, so that a cell of level l covers pixels [2^l c, 2^l (c + 1))
// on every level, and one texture holds every level: the march reads one texel a step. Only the
// cells that hold some of the screen are built (coveredSize); pixels past the screen count as 1,
// "nothing", in them. Level 0 is a copy of the depth buffer: the march reads
// it while the frame's depth is attached to the draw framebuffer for the depth test, and sampling
// an attachment is a feedback loop, undefined in OpenGL 4.5 (§9.3.1) even with depth writes off.
#pragma once

#include "gpu/program.h"
#include "gpu/texture.h"

namespace mirage {

// What the pyramid's behind limits are computed for: the surfaces' thickness (view-depth units)
// and the projection's planes.
struct HiZDepthRange {
  float thickness = 0.0f, near_plane = 0.1f, far_plane = 100.0f;
};

class HiZPyramid {
 public:
  HiZPyramid();

  // Copies `depth` (a depth texture of `screen` pixels) into level 0, padded, and builds levels
  // 1 and up from it, on the GPU.
  void build(const gpu::Texture& depth, ivec2 screen, const HiZDepthRange& range);

  // Every level, level 0 the padded copy of the depth buffer.
  const gpu::Texture& texture() const { return texture_; }
  int levels() const { return texture_.levels(); }
  ivec2 screen() const { return screen_; }
  // The pyramid's side lengths at level 0: `screen` rounded up to powers of two.
  static ivec2 paddedSize(ivec2 screen);
  // Its side lengths at `level`.
  static ivec2 levelSize(ivec2 screen, int level);
  // The cells of `level` that hold a pixel of the screen: the build writes only these (their
  // texels past them stay undefined), and a march clipped to the screen reads only these.
  static ivec2 coveredSize(ivec2 screen, int level);

 private:
  gpu::Program program_;
  gpu::Texture texture_;  // rg32f
  ivec2 screen_{0};
};

}  // namespace mirage
