// The curved reflectors' distance pyramid (zexel_bounds_shared.h): per cube of a
// depth-preserving cube-map array, level 0 the distances it stores, each level from
// ZEXEL_BOUND_FIRST_LEVEL to zexel_bound_top_level a lower bound of the distances the inverse
// warp could read near a texel, so that the search crosses empty stretches of a ray's epipolar
// line in one read; and each cube's farthest finite distance, beyond which a ray can hit
// nothing the cube holds. Built on the GPU (zexel_distance_pyramid.comp) after the cubes'
// captures.
#pragma once

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"

namespace mirage {

class ZexelDistancePyramid {
 public:
  ZexelDistancePyramid();

  // Builds the pyramid of every cube of `cubes` (an RGBA32F cube-map array: alpha the distance),
  // making room when their number or size changed.
  void build(const gpu::Texture& cubes);
  // Binds it for the search (MIRAGE_UNIT_ZEXEL_DISTANCES: bilinear within a level; the
  // farthest distances at MIRAGE_BIND_ZEXEL_FAR).
  void bind() const;
  // The coarsest level the search reads (0: none).
  int topLevel() const { return top_level_; }

 private:
  gpu::Program copy_, reduce_, bound_, farthest_;
  gpu::Texture pyramid_;  // R32F cube-map array: the distances, then the bounds B_L
  gpu::Texture reduced_;  // RG32F: the reductions M_L, and the farthest finite distance below
  gpu::Buffer far_;       // float a cube
  int top_level_ = 0;
};

}  // namespace mirage
