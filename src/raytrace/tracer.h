// The ground truth: Embree traces the full triangle meshes, recursively to order K, with the
// shading model that the GPU methods use (shading/shading.h) and the same environment texels.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "core/camera.h"
#include "core/image.h"
#include "raytrace/ray_scene.h"
#include "scene/environment.h"
#include "scene/scene.h"

namespace mirage {

struct TraceSettings {
  int order = 2;  // reflection order K: reflectors reached after K bounces show their base colour
  int spp = 1;    // samples per pixel (stratified, box filter); 1 = the pixel centre
};

struct TraceStats {
  double ms = 0.0;          // wall time of the frame
  double direct_ms = 0.0;   // share of it spent on primary rays and direct shading
  double reflect_ms = 0.0;  // share spent on reflected rays
  uint64_t primary_rays = 0, reflected_rays = 0;
};

struct TraceResult {
  Image color;  // linear radiance; alpha: distance from the eye (MISS_DISTANCE for the sky)
  IdImage ids;  // reflector id of the pixel centre's primary hit
  TraceStats stats;
};

// What a ray found: radiance and the distance to the first hit.
struct TracedRadiance {
  vec3 radiance{0.0f};
  float distance = 0.0f;
};

class RayTracer {
 public:
  RayTracer(const Scene& scene, const EnvironmentMap& environment);

  // Builds the BVH for `time` unless it is already built for it; returns the build ms (or 0).
  double prepare(float time);
  TraceResult render(const View& view, const TraceSettings& settings) const;
  // The radiance along one ray with `bounces_left` reflections still allowed.
  TracedRadiance trace(const Ray& ray, int bounces_left, uint64_t& reflected_rays) const;

  const RayScene& rayScene() const { return ray_scene_; }

 private:
  struct SurfacePoint;
  SurfacePoint surface(const RayHit& hit) const;
  vec3 shadeHit(const Ray& ray, const RayHit& hit, int bounces_left, uint64_t& reflected_rays) const;
  vec3 sampleTexture(int texture, vec2 uv) const;

  const Scene& scene_;
  const EnvironmentMap& environment_;
  RayScene ray_scene_;
  std::vector<int> reflector_id_;  // per instance: 1-based reflector id, 0 if diffuse
  float epsilon_ = 1e-4f;
};

}  // namespace mirage
