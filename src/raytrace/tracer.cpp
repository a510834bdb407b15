#include "raytrace/tracer.h"

#include <chrono>

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/timer.h"
#include "shading/shading.h"

namespace mirage {

namespace sh = shading;

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
  epsilon_ = 1e-5f * std::max(scene.bounds().radius(), 1e-3f);
}

double RayTracer::prepare(float time) {
  if (ray_scene_.builtTime() == time) return 0.0;
  return ray_scene_.build(time);
}

RayTracer::SurfacePoint RayTracer::surface(const RayHit& hit) const {
  const Instance& inst = scene_.instances[size_t(hit.instance)];
  const Mesh& mesh = scene_.meshes[size_t(inst.mesh)];
  const uvec3 tri = mesh.triangles[hit.primitive];
  const auto& world = ray_scene_.worldPositions(hit.instance);
  const mat4& model = ray_scene_.instanceMatrix(hit.instance);
  float w0 = 1.0f - hit.u - hit.v, w1 = hit.u, w2 = hit.v;
  SurfacePoint s;
  s.material = inst.material;
  s.position = w0 * world[tri.x] + w1 * world[tri.y] + w2 * world[tri.z];
  vec3 ng = glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]);
  float len = glm::length(ng);
  s.geometric = len > 0.0f ? ng / len : vec3(0, 1, 0);
  if (!mesh.normals.empty()) {
    vec3 n = w0 * mesh.normals[tri.x] + w1 * mesh.normals[tri.y] + w2 * mesh.normals[tri.z];
    n = normalMatrix(model) * n;
    float nl = glm::length(n);
    s.normal = nl > 0.0f ? n / nl : s.geometric;
  } else {
    s.normal = s.geometric;
  }
  if (!mesh.uvs.empty()) s.uv = w0 * mesh.uvs[tri.x] + w1 * mesh.uvs[tri.y] + w2 * mesh.uvs[tri.z];
  if (!mesh.tangents.empty()) {
    vec4 t = w0 * mesh.tangents[tri.x] + w1 * mesh.tangents[tri.y] + w2 * mesh.tangents[tri.z];
    s.tangent = vec4(mat3(model) * vec3(t), mesh.tangents[tri.x].w);
  }
  return s;
}

vec3 RayTracer::sampleTexture(int texture, vec2 uv) const {
  const Image& img = scene_.textures[size_t(texture)].image;
  // Bilinear, repeating, level 0 (the GPU's level 0 with GL_REPEAT).
  float x = uv.x * float(img.width()) - 0.5f, y = (1.0f - uv.y) * float(img.height()) - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int xi, int yi) {
    xi = ((xi % img.width()) + img.width()) % img.width();
    yi = ((yi % img.height()) + img.height()) % img.height();
    return vec3(img(xi, yi));
  };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx),
                  glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

vec3 RayTracer::shadeHit(const Ray& ray, const RayHit& hit, int bounces_left,
                         uint64_t& reflected_rays) const {
  SurfacePoint s = surface(hit);
  const Material& material = scene_.materials[size_t(s.material)];
  sh::MaterialData m = material.gpuData();
  vec3 n = s.normal;
  if (material.normal_map >= 0) n = sh::perturb_normal(n, s.tangent, sampleTexture(material.normal_map, s.uv));
  if (!material.isReflector()) {
    vec3 albedo = sh::material_albedo(m, s.uv);
    if (material.albedo_texture >= 0) albedo *= sampleTexture(material.albedo_texture, s.uv);
    return sh::shade_diffuse(albedo, n, scene_.light.direction, scene_.light.color, scene_.light.ambient);
  }
  if (bounces_left <= 0) return sh::reflector_base(m);
  vec3 to_viewer = -glm::normalize(ray.direction);
  vec3 facing = sh::facing_normal(n, s.geometric, to_viewer);
  vec3 r = sh::reflect_direction(-to_viewer, facing);
  // Leave the surface on the side the reflected ray goes to.
  vec3 side = glm::dot(s.geometric, r) >= 0.0f ? s.geometric : -s.geometric;
  Ray reflected{s.position + side * epsilon_, r, 0.0f, kInfinity};
  ++reflected_rays;
  TracedRadiance incoming = trace(reflected, bounces_left - 1, reflected_rays);
  float cos_theta = std::max(glm::dot(facing, to_viewer), 0.0f);
  return sh::shade_reflector(m, cos_theta, incoming.distance, incoming.radiance);
}

TracedRadiance RayTracer::trace(const Ray& ray, int bounces_left, uint64_t& reflected_rays) const {
  RayHit hit = ray_scene_.intersect(ray);
  if (!hit.hit()) return {environment_.sample(ray.direction), sh::MISS_DISTANCE};
  float distance = hit.t * glm::length(ray.direction);
  return {shadeHit(ray, hit, bounces_left, reflected_rays), distance};
}

TraceResult RayTracer::render(const View& view, const TraceSettings& settings) const {
  const ivec2 size = view.size();
  TraceResult result;
  result.color = Image(size.x, size.y);
  result.ids = IdImage(size.x, size.y);
  // Stratified sub-pixel positions: an n x n grid holding spp samples.
  const int spp = std::max(settings.spp, 1);
  const int grid = int(std::ceil(std::sqrt(double(spp))));
  constexpr int kTile = 16;
  const int tiles_x = (size.x + kTile - 1) / kTile, tiles_y = (size.y + kTile - 1) / kTile;
  Progress progress("raytrace", size_t(tiles_x) * size_t(tiles_y));
  tbb::combinable<double> direct_cpu, reflect_cpu;
  std::atomic<uint64_t> primary_total{0}, reflected_total{0};
  Stopwatch wall;

  struct Pending {
    Ray ray;
    RayHit hit;
    int pixel;
  };
  tbb::parallel_for(tbb::blocked_range2d<int>(0, tiles_y, 0, tiles_x), [&](const auto& range) {
    std::vector<Pending> pending;
    for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty)
      for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
        Stopwatch phase;
        pending.clear();
        uint64_t primary = 0, reflected = 0;
        int x1 = std::min((tx + 1) * kTile, size.x), y1 = std::min((ty + 1) * kTile, size.y);
        // Pass 1: primary rays; diffuse surfaces and the sky are shaded at once.
        for (int y = ty * kTile; y < y1; ++y)
          for (int x = tx * kTile; x < x1; ++x) {
            int pixel = y * size.x + x;
            vec3 sum(0.0f);
            RayHit centre_hit;
            for (int s = 0; s < spp; ++s) {
              float sx = spp == 1 ? 0.5f : (float(s % grid) + 0.5f) / float(grid);
              float sy = spp == 1 ? 0.5f : (float(s / grid) + 0.5f) / float(grid);
              Ray ray = view.primaryRay(float(x) + sx, float(y) + sy);
              RayHit hit = ray_scene_.intersect(ray);
              ++primary;
              if (spp == 1) centre_hit = hit;
              if (!hit.hit()) sum += environment_.sample(ray.direction);
              else if (reflector_id_[size_t(hit.instance)] == 0) sum += shadeHit(ray, hit, 0, reflected);
              else pending.push_back({ray, hit, pixel});
            }
            // The ID and distance come from the pixel centre, as the rasteriser's do.
            if (spp > 1) centre_hit = ray_scene_.intersect(view.primaryRay(float(x) + 0.5f, float(y) + 0.5f));
            result.ids(x, y) = centre_hit.hit() ? uint32_t(reflector_id_[size_t(centre_hit.instance)]) : 0u;
            float distance = centre_hit.hit() ? centre_hit.t : sh::MISS_DISTANCE;
            result.color(x, y) = vec4(sum / float(spp), distance);
          }
        direct_cpu.local() += phase.ms();
        phase.restart();
        // Pass 2: the reflections of the reflector samples.
        for (const Pending& p : pending) {
          vec3 c = shadeHit(p.ray, p.hit, settings.order, reflected);
          vec4& out = result.color.data()[p.pixel];
          out = vec4(vec3(out) + c / float(spp), out.w);
        }
        reflect_cpu.local() += phase.ms();
        primary_total += primary;
        reflected_total += reflected;
        progress.advance();
      }
  });
  result.stats.ms = wall.ms();
  double d = direct_cpu.combine(std::plus<double>()), r = reflect_cpu.combine(std::plus<double>());
  double share = d + r > 0.0 ? d / (d + r) : 1.0;
  result.stats.direct_ms = result.stats.ms * share;
  result.stats.reflect_ms = result.stats.ms * (1.0 - share);
  result.stats.primary_rays = primary_total;
  result.stats.reflected_rays = reflected_total;
  return result;
}

}  // namespace mirage
