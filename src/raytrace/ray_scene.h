// The scene in Embree 3: one triangle geometry per instance, in world space at a given time
// (geometry ID = instance index). The Embree scene lives as long as the RayScene; when the scene
// moves, the moved instances' vertices are rewritten and the BVH built again. The build is timed
// apart from tracing so benchmarks can report it separately.
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

  // Brings the scene to `time`: rewrites the vertices of the instances that moved or deformed
  // since the last build, rebuilds the BVH and returns the build time in ms; returns 0 when the
  // triangles are the same (the light may still have moved).
  double build(float time);
  float builtTime() const { return time_; }
  const mat4& instanceMatrix(int instance) const { return matrices_[size_t(instance)]; }
  // normalMatrix(instanceMatrix(i)) and mat3(instanceMatrix(i)), computed once per build
  // rather than once per hit (the values are the very same floats).
  const mat3& normalMatrixOf(int instance) const { return normal_matrices_[size_t(instance)]; }
  const mat3& linearPartOf(int instance) const { return linear_parts_[size_t(instance)]; }
  // World-space vertex positions of an instance.
  const std::vector<vec3>& worldPositions(int instance) const { return world_[size_t(instance)]; }
  // The instance's mesh in object space at builtTime(): its deformed copy when it deforms.
  const Mesh& mesh(int instance) const;
  // The light at builtTime().
  const Light& light() const { return light_; }

  RayHit intersect(const Ray& ray) const;
  // The same hits as intersect() on each ray, for n rays, traced 16 at a time (see the .cpp).
  void intersect(const Ray* rays, RayHit* hits, size_t n) const;
  // The Embree scene and device, for packet/stream queries and benchmarks (null before build).
  RTCScene handle() const { return rtc_scene_; }
  RTCDevice device() const { return device_; }

 private:
  bool sameGeometryAt(float time) const;

  const Scene& scene_;
  RTCDevice device_ = nullptr;
  RTCScene rtc_scene_ = nullptr;
  std::vector<RTCGeometry> geometries_;  // geometry ID = instance index
  std::vector<mat4> matrices_;
  std::vector<mat3> normal_matrices_, linear_parts_;
  std::vector<std::vector<vec3>> world_;
  std::vector<Mesh> deformed_;  // per instance: the mesh at time_ (empty unless it deforms)
  Light light_;
  float time_ = -1.0f;
};

}  // namespace mirage
