// How the hybrid method's point samples cover an object's surface: stratified, so that no gap
// opens wider than its neighbours' spacing, and each point with a spacing of its own, so that its
// splat closes the gaps around it. Independent uniform samples leave random gaps wider than their
// mean spacing, and a splat the size of the mean spacing leaves holes there once a concave mirror
// magnifies the object (concave-dish: 3.9 % of the ball's pixels empty).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace mirage {

// The neighbours each point's spacing is measured to: the distance to its k-th nearest one. Six,
// the neighbours of a point in a hexagonal packing: a square splat of that side reaches them.
inline constexpr int kSpacingNeighbours = 6;
inline constexpr float kSpacingScale = 0.8f;

// Each point's spacing: the distance to its kSpacingNeighbours-th nearest neighbour, at most
// `most` (a stray point far from the others keeps a bounded splat). `mean_spacing` sizes the
// search grid (sqrt(area / count) of the surface).
std::vector<float> neighbourSpacings(std::span<const vec3> positions, float mean_spacing,
                                     float most);

// A Poisson-disk subset of `target` points out of `candidates` on a surface of `area`: weighted
// sample elimination (Yuksel, "Sample Elimination for Generating Poisson Disk Sample Sets",
// 2015), which removes the candidate most crowded by its neighbours within 2 r_max until
// `target` remain (r_max = sqrt(area / (2 sqrt(3) target)), the largest Poisson-disk radius of
// `target` points; weights (1 - d / 2 r_max)^8 with the paper's weight limiting). The first
// `fixed` candidates (an object's mesh vertices) are never removed but crowd the others.
// Returns the indices kept, ascending; deterministic.
std::vector<uint32_t> eliminateSamples(std::span<const vec3> candidates, size_t fixed,
                                       size_t target, double area);

}  // namespace mirage
