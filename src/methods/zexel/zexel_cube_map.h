// A depth-preserving cube map in memory — per direction from its centre, the colour and the
// distance to what the centre saw there — and the inverse warp over it: the very search the
// curved-reflector shader runs (zexel_inverse_shared.h), with the map read as the GPU filters
// its copy (bilinear on level 0, seamless across faces). The tests search maps ray-cast on the
// CPU; the host takes the search's settings from here, so that both step alike.
#pragma once

#include <array>
#include <vector>

#include "core/math.h"
#include "shading/shading.h"

namespace mirage {

struct ZexelCubeMap {
  using Faces = std::array<std::vector<float>, 6>;

  int size = 0;                            // face size in texels
  vec3 centre{0.0f};                       // the reference centre
  std::array<std::vector<vec4>, 6> faces;  // GL face order; rgb; a: distance (MISS_DISTANCE: sky)
  // The lower bounds of the distances (zexel_bounds_shared.h) by level, as the GPU's pyramid
  // holds them (levels below ZEXEL_BOUND_FIRST_LEVEL empty); none until buildBounds.
  std::vector<Faces> bounds;
  float far = shading::MISS_DISTANCE;  // the farthest finite distance, once buildBounds ran

  vec4 texel(int face, int x, int y) const {
    return faces[size_t(face)][size_t(y) * size_t(size) + size_t(x)];
  }
  // Bilinear on level 0, seamless across faces, as GL samples the GPU copy; `d` need not be unit.
  vec4 sample(const vec3& d) const;
  // The bound of `level` along `d`, bilinear and seamless likewise.
  float bound(int level, const vec3& d) const;
  // Builds `bounds` up to zexel_bound_top_level(size), as zexel_distance_pyramid.comp does.
  void buildBounds();
  // The unit direction through the centre of texel (x, y) of `face`.
  vec3 texelDirection(int face, int x, int y) const;
};

// How the search steps through a map.
struct ZexelInverseSettings {
  float step_angle = 0.0f;   // radians per step
  int max_steps = 1;         // enough for the longest epipolar line (π) at that step
  float max_slope = 20.0f;   // the steepest stored surface, dD/dφ / D (see below)
  float texel_angle = 0.0f;  // a level-0 texel's angle at a face's centre
  int top_level = 0;         // the coarsest level of bounds read (0: none, a linear search)
};

// Steps of `step_texels` texels of a `face_size` map: a texel's mean angle along a face's centre
// line is π / (2 · face_size). The slope limit, 20 (a surface seen 87° off the centre's line
// of sight: a floor far towards the horizon), is steeper than the surfaces of the scenes and
// gentler than a discontinuity's interpolated ramp unless its two sides lie within
// 20 · π / (2 · face_size) of each other in relative distance (12 % at 256).
// With `bounds`, the search crosses empty stretches with the bounds up to
// zexel_bound_top_level(face_size) (the map's bounds must be built).
ZexelInverseSettings zexelInverseSettings(int face_size, float step_texels, bool bounds = true);
// The worst case of zexel_inverse_warp's loops in one invocation (gpu/loop_budget.h): the march
// start's walk up the bound levels, then the one loop of (max_steps + 1) x (bisections + 2)
// iterations, marching, skipping or bisecting.
long long zexelInverseLoopCost(const ZexelInverseSettings& settings);

// What a search found: ZEXEL_INVERSE_* of zexel_inverse_shared.h (static_assert'ed equal).
inline constexpr int kZexelInverseSky = 0, kZexelInverseHit = 1, kZexelInverseExposed = 2;

struct ZexelInverseHit {
  float t = -1.0f;                // along the unit ray; < 0: no hit (the sky)
  vec3 direction{0.0f};           // from the map's centre to the hit
  int status = kZexelInverseSky;  // or kZexelInverseHit, kZexelInverseExposed
  int samples = 0;                // map reads
};

// The inverse warp of the ray origin + t dir (world space) through `map`.
ZexelInverseHit zexelInverseWarp(const ZexelCubeMap& map, const vec3& origin, const vec3& dir,
                                 const ZexelInverseSettings& settings);

}  // namespace mirage
