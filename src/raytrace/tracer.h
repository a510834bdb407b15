// The ground truth: Embree traces the full triangle meshes, recursively to order K, with the
// shading model that the GPU methods use (shading/shading.h) and the same environment texels.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "core/camera.h"
#include "core/first_hit.h"
#include "core/image.h"
#include "raytrace/ray_scene.h"
#include "scene/environment.h"
#include "scene/scene.h"
#include "shading/gpu_types.h"

namespace mirage {

struct TraceSettings {
  int order = 2;  // reflection order K: reflectors reached after K bounces show their base colour
  int spp = 1;    // samples per pixel (stratified, box filter); 1 = the pixel centre
  // When set and true, the remaining tiles are skipped (the image is then incomplete): the
  // viewer's background reference stops this way when the camera moves.
  const std::atomic<bool>* cancel = nullptr;
  bool progress = true;  // a progress bar on a terminal (background renders draw none)
  // false: each sample at the centre of its stratum (a regular n x n grid: spp = N^2 traces the
  // sub-pixel centres of --ssaa N exactly). true: at a random point of its stratum (a hash of the
  // pixel and the sample, the same every run), so that a converged reference shares no position
  // with any regular grid it checks.
  bool jitter = false;
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
  // The same frame into `out`, reusing its images when their size matches: callers that render
  // frame after frame save the page faults of fresh 7-15 MB images (every pixel is rewritten).
  void render(const View& view, const TraceSettings& settings, TraceResult& out) const;
  // The straightforward implementation render() replaced: every per-hit quantity (normal
  // matrix, material data) recomputed at each hit, a separate centre ray per pixel when
  // spp > 1. Kept as the reference that render() must match bit for bit (tests/raytrace).
  TraceResult renderReference(const View& view, const TraceSettings& settings) const;
  // Per pixel, what the reflected ray of the pixel centre's primary hit meets first
  // (core/first_hit.h: 0 where the primary ray hits no reflector), at reflection order `order`:
  // the same primary rays and reflected rays as render(), for error attribution.
  IdImage firstHits(const View& view, int order) const;
  // The radiance along one ray with `bounces_left` reflections still allowed.
  TracedRadiance trace(const Ray& ray, int bounces_left, uint64_t& reflected_rays) const;

  const RayScene& rayScene() const { return ray_scene_; }

 private:
  struct SurfacePoint;
  // The mirror-reflected ray leaving a surface point, and what shading needs of it.
  struct Reflection {
    Ray ray;
    vec3 facing, to_viewer;
  };
  vec3 shadingNormal(const Material& material, const SurfacePoint& s) const;
  Reflection reflection(const Ray& ray, const SurfacePoint& s, vec3 n) const;
  uint32_t firstHit(const Ray& primary, int order) const;
  // kReference selects the original per-hit computations; both give the same floats.
  template <bool kReference>
  SurfacePoint surface(const RayHit& hit, bool reflector) const;
  template <bool kReference>
  vec3 shadeHit(const Ray& ray, const RayHit& hit, int bounces_left,
                uint64_t& reflected_rays) const;
  template <bool kReference>
  TracedRadiance traceRay(const Ray& ray, int bounces_left, uint64_t& reflected_rays) const;
  struct PixelSamples;
  struct TileScratch;
  void traceTilePrimaries(const View& view, const PixelSamples& samples, int tx, int ty,
                          TileScratch& scratch) const;
  template <bool kReference>
  void shadeTilePrimaries(const View& view, const PixelSamples& samples, int tx, int ty,
                          TileScratch& scratch, TraceResult& result) const;
  template <bool kReference>
  void renderTiles(const View& view, const TraceSettings& settings, TraceResult& result) const;
  vec3 sampleTexture(int texture, vec2 uv) const;

  const Scene& scene_;
  const EnvironmentMap& environment_;
  RayScene ray_scene_;
  std::vector<int> reflector_id_;  // per instance: 1-based reflector id, 0 if diffuse
  std::vector<shading::MaterialData> material_data_;  // per material: Material::gpuData()
  float epsilon_ = 1e-4f;
};

}  // namespace mirage
