#include "raytrace/tracer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "core/interrupt.h"
#include "core/progress.h"
#include "core/timer.h"
#include "shading/shading.h"

namespace mirage {

namespace sh = shading;

namespace {

// A point in [0, 1)^2 for sample s of pixel (x, y): two rounds of a 32-bit integer hash
// (Wellons' lowbias32), the same on every run and machine.
uint32_t hash32(uint32_t v) {
  v ^= v >> 16;
  v *= 0x7feb352du;
  v ^= v >> 15;
  v *= 0x846ca68bu;
  v ^= v >> 16;
  return v;
}

vec2 strataJitter(uint32_t x, uint32_t y, uint32_t s) {
  const uint32_t a = hash32(x * 0x9e3779b9u ^ hash32(y * 0x85ebca6bu ^ hash32(s)));
  const uint32_t b = hash32(a ^ 0x68e31da4u);
  return vec2(float(a >> 8), float(b >> 8)) * (1.0f / 16777216.0f);
}

}  // namespace

struct RayTracer::SurfacePoint {
  vec3 position;
  vec3 normal;     // interpolated shading normal (unit), before normal mapping
  vec3 geometric;  // unit geometric normal (winding orientation)
  vec2 uv{0.0f};
  vec4 tangent{1, 0, 0, 1};
  int material = 0;
};

RayTracer::RayTracer(const Scene& scene, const EnvironmentMap& environment)
    : scene_(scene), environment_(environment), ray_scene_(scene) {
  reflector_id_.assign(scene.instances.size(), 0);
  std::vector<int> reflectors = scene.reflectorInstances();
  for (size_t r = 0; r < reflectors.size(); ++r) reflector_id_[size_t(reflectors[r])] = int(r) + 1;
  material_data_.reserve(scene.materials.size());
  for (const Material& material : scene.materials) material_data_.push_back(material.gpuData());
  epsilon_ = 1e-5f * std::max(scene.bounds().radius(), 1e-3f);
}

double RayTracer::prepare(float time) {
  if (ray_scene_.builtTime() == time) return 0.0;
  return ray_scene_.build(time);
}

template <bool kReference>
RayTracer::SurfacePoint RayTracer::surface(const RayHit& hit, bool reflector) const {
  const Instance& inst = scene_.instances[size_t(hit.instance)];
  const Mesh& mesh = ray_scene_.mesh(hit.instance);
  const uvec3 tri = mesh.triangles[hit.primitive];
  const auto& world = ray_scene_.worldPositions(hit.instance);
  const mat4& model = ray_scene_.instanceMatrix(hit.instance);
  float w0 = 1.0f - hit.u - hit.v, w1 = hit.u, w2 = hit.v;
  auto geometric = [&] {
    vec3 ng = glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]);
    float len = glm::length(ng);
    return len > 0.0f ? ng / len : vec3(0, 1, 0);
  };
  SurfacePoint s;
  s.material = inst.material;
  // Diffuse shading reads neither the position nor the geometric normal: render() skips them
  // there (the values it does compute are the reference's, operation for operation).
  const bool full = kReference || reflector || mesh.normals.empty();
  if (full) {
    s.position = w0 * world[tri.x] + w1 * world[tri.y] + w2 * world[tri.z];
    s.geometric = geometric();
  }
  if (!mesh.normals.empty()) {
    vec3 n = w0 * mesh.normals[tri.x] + w1 * mesh.normals[tri.y] + w2 * mesh.normals[tri.z];
    // The inverse transpose once per build instead of once per hit: the same matrix.
    n = (kReference ? normalMatrix(model) : ray_scene_.normalMatrixOf(hit.instance)) * n;
    float nl = glm::length(n);
    s.normal = nl > 0.0f ? n / nl : (full ? s.geometric : geometric());
  } else {
    s.normal = s.geometric;
  }
  if (!mesh.uvs.empty()) s.uv = w0 * mesh.uvs[tri.x] + w1 * mesh.uvs[tri.y] + w2 * mesh.uvs[tri.z];
  if (!mesh.tangents.empty()) {
    vec4 t = w0 * mesh.tangents[tri.x] + w1 * mesh.tangents[tri.y] + w2 * mesh.tangents[tri.z];
    const mat3 linear = kReference ? mat3(model) : ray_scene_.linearPartOf(hit.instance);
    s.tangent = vec4(linear * vec3(t), mesh.tangents[tri.x].w);
  }
  return s;
}

vec3 RayTracer::sampleTexture(int texture, vec2 uv) const {
  return mirage::sampleTexture(scene_.textures[size_t(texture)].image, uv);
}

vec3 RayTracer::shadingNormal(const Material& material, const SurfacePoint& s) const {
  if (material.normal_map < 0) return s.normal;
  return sh::perturb_normal(s.normal, s.tangent, sampleTexture(material.normal_map, s.uv));
}

RayTracer::Reflection RayTracer::reflection(const Ray& ray, const SurfacePoint& s, vec3 n) const {
  Reflection out;
  out.to_viewer = -glm::normalize(ray.direction);
  out.facing = sh::facing_normal(n, s.geometric, out.to_viewer);
  vec3 r = sh::reflect_direction(-out.to_viewer, out.facing);
  // Leave the surface on the side the reflected ray goes to.
  vec3 side = glm::dot(s.geometric, r) >= 0.0f ? s.geometric : -s.geometric;
  out.ray = Ray{s.position + side * epsilon_, r, 0.0f, kInfinity};
  return out;
}

template <bool kReference>
vec3 RayTracer::shadeHit(const Ray& ray, const RayHit& hit, int bounces_left,
                         uint64_t& reflected_rays) const {
  const int material_index = scene_.instances[size_t(hit.instance)].material;
  const Material& material = scene_.materials[size_t(material_index)];
  SurfacePoint s = surface<kReference>(hit, material.isReflector());
  // The reference converts the material at every hit; render() reads the converted copy.
  const sh::MaterialData m =
      kReference ? material.gpuData() : material_data_[size_t(material_index)];
  const vec3 n = shadingNormal(material, s);
  if (!material.isReflector()) {
    vec3 albedo = sh::material_albedo(m, s.uv);
    if (material.albedo_texture >= 0) albedo *= sampleTexture(material.albedo_texture, s.uv);
    const Light& light = ray_scene_.light();
    return sh::shade_diffuse(albedo, n, light.direction, light.color, light.ambient);
  }
  if (bounces_left <= 0) return sh::reflector_base(m);
  const Reflection reflected = reflection(ray, s, n);
  ++reflected_rays;
  TracedRadiance incoming = traceRay<kReference>(reflected.ray, bounces_left - 1, reflected_rays);
  float cos_theta = std::max(glm::dot(reflected.facing, reflected.to_viewer), 0.0f);
  return sh::shade_reflector(m, cos_theta, incoming.distance, incoming.radiance);
}

template <bool kReference>
TracedRadiance RayTracer::traceRay(const Ray& ray, int bounces_left,
                                   uint64_t& reflected_rays) const {
  // Reflected rays are incoherent: Embree's single-ray kernel is the fastest for them, and
  // the only one whose hits the reference reproduces (see docs/benchmarks.md).
  RayHit hit = ray_scene_.intersect(ray);
  if (!hit.hit()) return {environment_.sample(ray.direction), sh::MISS_DISTANCE};
  float distance = hit.t * glm::length(ray.direction);
  return {shadeHit<kReference>(ray, hit, bounces_left, reflected_rays), distance};
}

TracedRadiance RayTracer::trace(const Ray& ray, int bounces_left, uint64_t& reflected_rays) const {
  return traceRay<false>(ray, bounces_left, reflected_rays);
}

uint32_t RayTracer::firstHit(const Ray& primary, int order) const {
  const RayHit hit = ray_scene_.intersect(primary);
  if (!hit.hit() || reflector_id_[size_t(hit.instance)] == 0) return 0;
  if (order <= 0) return encodeFirstHit(FirstHit::kBeyondOrder, -1);
  const Material& material =
      scene_.materials[size_t(scene_.instances[size_t(hit.instance)].material)];
  const SurfacePoint s = surface<false>(hit, true);
  const RayHit next = ray_scene_.intersect(reflection(primary, s, shadingNormal(material, s)).ray);
  if (!next.hit()) return encodeFirstHit(FirstHit::kEnvironment, -1);
  if (reflector_id_[size_t(next.instance)] == 0)
    return encodeFirstHit(FirstHit::kDiffuse, next.instance);
  if (order == 1) return encodeFirstHit(FirstHit::kBeyondOrder, next.instance);
  return encodeFirstHit(next.instance == hit.instance ? FirstHit::kSelf : FirstHit::kReflector,
                        next.instance);
}

IdImage RayTracer::firstHits(const View& view, int order) const {
  const ivec2 size = view.size();
  IdImage out(size.x, size.y);
  tbb::parallel_for(0, size.y, [&](int y) {
    if (interruptRequested()) return;
    for (int x = 0; x < size.x; ++x)
      out(x, y) = firstHit(view.primaryRay(float(x) + 0.5f, float(y) + 0.5f), order);
  });
  checkInterrupt();
  return out;
}

TraceResult RayTracer::render(const View& view, const TraceSettings& settings) const {
  TraceResult result;
  renderTiles<false>(view, settings, result);
  return result;
}

void RayTracer::render(const View& view, const TraceSettings& settings, TraceResult& out) const {
  renderTiles<false>(view, settings, out);
}

TraceResult RayTracer::renderReference(const View& view, const TraceSettings& settings) const {
  TraceResult result;
  renderTiles<true>(view, settings, result);
  return result;
}

// The sub-pixel positions of a pixel's samples: a stratified n x n grid holding spp samples,
// jittered within their strata or at their centres.
struct RayTracer::PixelSamples {
  int spp = 1, grid = 1;
  bool jitter = false;
  // The sample whose ray is the pixel-centre ray, or -1: then the centre is traced on its own.
  // The reference traces it separately whenever spp > 1; an odd grid has it among the samples.
  int centre_sample = 0;

  PixelSamples(const TraceSettings& settings, bool reference)
      : spp(std::max(settings.spp, 1)),
        grid(int(std::ceil(std::sqrt(double(spp))))),
        jitter(settings.jitter && spp > 1),
        centre_sample(spp == 1 ? 0 : -1) {
    if (!reference && !jitter)
      for (int s = 0; s < spp && centre_sample < 0; ++s)
        if (offset(0, 0, s) == vec2(0.5f)) centre_sample = s;
  }
  vec2 offset(int x, int y, int s) const {
    vec2 in_stratum(0.5f);
    if (jitter) in_stratum = strataJitter(uint32_t(x), uint32_t(y), uint32_t(s));
    float sx = spp == 1 ? 0.5f : (float(s % grid) + in_stratum.x) / float(grid);
    float sy = spp == 1 ? 0.5f : (float(s / grid) + in_stratum.y) / float(grid);
    return vec2(sx, sy);
  }
};

// One worker's buffers, reused from tile to tile, and its ray counts.
struct RayTracer::TileScratch {
  // A reflector sample whose reflection pass 2 traces.
  struct Pending {
    Ray ray;
    RayHit hit;
    int pixel;
  };
  std::vector<Pending> pending;
  std::vector<Ray> rays;  // the tile's primary rays, batched (not in the reference)
  std::vector<RayHit> hits;
  uint64_t primary = 0, reflected = 0;
};

namespace {

constexpr int kTile = 16;

// The tile's pixels: [x0, x1) x [y0, y1).
struct TileRect {
  int x0, y0, x1, y1;
};

TileRect tileRect(int tx, int ty, ivec2 size) {
  return {tx * kTile, ty * kTile, std::min((tx + 1) * kTile, size.x),
          std::min((ty + 1) * kTile, size.y)};
}

}  // namespace

// Primary rays go to Embree 16 at a time with the incoherent flag (RayScene::intersect(rays,
// hits, n)), which returns rtcIntersect1's hits and is 1.5-1.7x faster on them. Coherent
// packets (frustum traversal, packet triangle tests) would be faster still but return other hits
// on edges and ties: the ground truth must not depend on how rays are batched. Reflected rays
// stay single: packets gain little on them. docs/benchmarks.md has the measurements.
void RayTracer::traceTilePrimaries(const View& view, const PixelSamples& samples, int tx, int ty,
                                   TileScratch& scratch) const {
  const TileRect t = tileRect(tx, ty, view.size());
  // The tile's primary rays, in the order shadeTilePrimaries takes them.
  scratch.rays.clear();
  for (int y = t.y0; y < t.y1; ++y)
    for (int x = t.x0; x < t.x1; ++x) {
      for (int s = 0; s < samples.spp; ++s) {
        vec2 o = samples.offset(x, y, s);
        scratch.rays.push_back(view.primaryRay(float(x) + o.x, float(y) + o.y));
      }
      if (samples.centre_sample < 0)
        scratch.rays.push_back(view.primaryRay(float(x) + 0.5f, float(y) + 0.5f));
    }
  scratch.hits.resize(scratch.rays.size());
  ray_scene_.intersect(scratch.rays.data(), scratch.hits.data(), scratch.rays.size());
}

// Pass 1: primary rays; diffuse surfaces and the sky are shaded at once, reflector samples are
// kept for pass 2. Every pixel's id and distance come from its centre, as the rasteriser's do.
template <bool kReference>
void RayTracer::shadeTilePrimaries(const View& view, const PixelSamples& samples, int tx, int ty,
                                   TileScratch& scratch, TraceResult& result) const {
  const ivec2 size = view.size();
  const TileRect t = tileRect(tx, ty, size);
  size_t next = 0;                      // the next of scratch.rays/hits
  uint64_t primary = 0, reflected = 0;  // counted in registers, added to the scratch's at the end
  for (int y = t.y0; y < t.y1; ++y)
    for (int x = t.x0; x < t.x1; ++x) {
      int pixel = y * size.x + x;
      vec3 sum(0.0f);
      RayHit centre_hit;
      for (int s = 0; s < samples.spp; ++s) {
        Ray ray;
        RayHit hit;
        if (kReference) {
          vec2 o = samples.offset(x, y, s);
          ray = view.primaryRay(float(x) + o.x, float(y) + o.y);
          hit = ray_scene_.intersect(ray);
        } else {
          ray = scratch.rays[next];
          hit = scratch.hits[next++];
        }
        ++primary;
        if (s == samples.centre_sample) centre_hit = hit;
        if (!hit.hit())
          sum += environment_.sample(ray.direction);
        else if (reflector_id_[size_t(hit.instance)] == 0)
          sum += shadeHit<kReference>(ray, hit, 0, reflected);
        else
          scratch.pending.push_back({ray, hit, pixel});
      }
      if (samples.centre_sample < 0)
        centre_hit = kReference
                         ? ray_scene_.intersect(view.primaryRay(float(x) + 0.5f, float(y) + 0.5f))
                         : scratch.hits[next++];
      result.ids(x, y) =
          centre_hit.hit() ? uint32_t(reflector_id_[size_t(centre_hit.instance)]) : 0u;
      float distance = centre_hit.hit() ? centre_hit.t : sh::MISS_DISTANCE;
      result.color(x, y) = vec4(sum / float(samples.spp), distance);
    }
  scratch.primary += primary;
  scratch.reflected += reflected;
}

template <bool kReference>
void RayTracer::renderTiles(const View& view, const TraceSettings& settings,
                            TraceResult& result) const {
  const ivec2 size = view.size();
  // Pass 1 writes every pixel's colour and id: images of the right size are reused as they are.
  if (result.color.size() != size) result.color = Image(size.x, size.y);
  if (result.ids.size() != size) result.ids = IdImage(size.x, size.y);
  result.stats = {};
  const PixelSamples samples(settings, kReference);
  const int tiles_x = (size.x + kTile - 1) / kTile, tiles_y = (size.y + kTile - 1) / kTile;
  Progress progress("raytrace", settings.progress ? size_t(tiles_x) * size_t(tiles_y) : 0);
  tbb::combinable<double> direct_cpu, reflect_cpu;
  std::atomic<uint64_t> primary_total{0}, reflected_total{0};
  Stopwatch wall;
  tbb::parallel_for(tbb::blocked_range2d<int>(0, tiles_y, 0, tiles_x), [&](const auto& range) {
    TileScratch scratch;
    scratch.pending.reserve(size_t(kTile) * size_t(kTile) * size_t(samples.spp));
    for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty)
      for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
        if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) return;
        if (interruptRequested()) return;
        Stopwatch phase;
        scratch.pending.clear();
        scratch.primary = scratch.reflected = 0;
        if (!kReference) traceTilePrimaries(view, samples, tx, ty, scratch);
        shadeTilePrimaries<kReference>(view, samples, tx, ty, scratch, result);
        direct_cpu.local() += phase.ms();
        phase.restart();
        // Pass 2: the reflections of the reflector samples.
        for (const TileScratch::Pending& p : scratch.pending) {
          vec3 c = shadeHit<kReference>(p.ray, p.hit, settings.order, scratch.reflected);
          vec4& out = result.color.data()[p.pixel];
          out = vec4(vec3(out) + c / float(samples.spp), out.w);
        }
        reflect_cpu.local() += phase.ms();
        primary_total += scratch.primary;
        reflected_total += scratch.reflected;
        progress.advance();
      }
  });
  // Ctrl-C: the tiles stopped early; a caller with its own cancel flag (the viewer's background
  // reference) takes the partial frame and stops itself, any other gets Interrupted.
  if (!settings.cancel) checkInterrupt();
  result.stats.ms = wall.ms();
  double d = direct_cpu.combine(std::plus<double>()), r = reflect_cpu.combine(std::plus<double>());
  double share = d + r > 0.0 ? d / (d + r) : 1.0;
  result.stats.direct_ms = result.stats.ms * share;
  result.stats.reflect_ms = result.stats.ms * (1.0 - share);
  result.stats.primary_rays = primary_total;
  result.stats.reflected_rays = reflected_total;
}

}  // namespace mirage
