// The scene in Embree 3: one triangle geometry per instance, in world space at a given time
// (geometry ID = instance index). Rebuilt when the scene moves; the build is timed apart from
// tracing so benchmarks can report it separately.
#pragma once

#include <embree3/rtcore.h>

#include "core/ray.h"
#include "scene/scene.h"

namespace mirage {

struct RayHit {
  float t = kInfinity;
  int instance = -1;  // -1: miss
  unsigned primitive = 0;
  float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2
  bool hit() const { return instance >= 0; }
};

class RayScene {
 public:
  explicit RayScene(const Scene& scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // (Re)builds the BVH for the instances at `time`; returns the build time in ms.
  double build(float time);
  float builtTime() const { return time_; }
  const mat4& instanceMatrix(int instance) const { return matrices_[size_t(instance)]; }
  // World-space vertex positions of an instance.
  const std::vector<vec3>& worldPositions(int instance) const { return world_[size_t(instance)]; }

  RayHit intersect(const Ray& ray) const;

 private:
  const Scene& scene_;
  RTCDevice device_ = nullptr;
  RTCScene rtc_scene_ = nullptr;
  std::vector<mat4> matrices_;
  std::vector<std::vector<vec3>> world_;
  float time_ = -1.0f;
};

}  // namespace mirage
