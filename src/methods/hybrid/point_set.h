// The point samples of the hybrid method (the hybrid paper, §3.1): every non-planar diffuse
// object near the reflectors becomes a set of points in its own object space — its mesh's
// vertices, or uniform samples of its surface to reach a requested count — each with the
// object-space normal and the albedo the shared shading model needs. Shading happens per frame
// on the GPU with the instance's current transform, so rigid motion changes nothing here.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace mirage {

struct PointSetOptions {
  // 0: each object's mesh vertices. N > 0: N points over all objects, shared by world surface
  // area; an object whose share reaches its vertex count keeps its vertices and adds uniform
  // surface samples, a smaller share is all uniform samples.
  long long total = 0;
  // With total 0: when all the objects' vertices together are fewer than this, `minimum`
  // points are taken as if it were the total (vertices kept, topped up by surface samples).
  long long minimum = 0;
  uint32_t seed = 1;
};

// The points of one instance, in its object space.
struct PointSet {
  int instance = -1;
  std::vector<vec3> positions;
  std::vector<vec3> normals;  // unit
  std::vector<vec3> albedo;   // linear, texture and checker applied
  // Each point's spacing: the distance to its kSpacingNeighbours-th nearest neighbour
  // (point_spacing.h), what its splat must span to reach its neighbours.
  std::vector<float> spacings;
  size_t vertex_points = 0;  // how many are mesh vertices (the rest are surface samples)
  float spacing = 0.0f;      // the mean distance between neighbours: sqrt(area / count)
  bool closed = false;       // the mesh is a closed surface: its back-facing points are hidden

  size_t size() const { return positions.size(); }
  // Reorders every attribute: new[i] = old[order[i]].
  void permute(const std::vector<uint32_t>& order);
};

// The instances the hybrid method reflects as points: the object layer's (scene/layers.h) that
// are not planar. The environment layer (a room, a floor) and planar objects stay in the
// background the points are splatted over.
std::vector<int> pointSampledInstances(const Scene& scene);

// The point sets of `instances` (empty sets are dropped).
std::vector<PointSet> samplePoints(const Scene& scene, const std::vector<int>& instances,
                                   const PointSetOptions& options);

}  // namespace mirage
