#include "bench_scenes.h"

#include <cstring>
#include <map>
#include <mutex>

#include "scene/builtin_scenes.h"
#include "shading/shading.h"

namespace mirage::bench {

namespace {

// The reflected ray the tracer would follow from a primary hit on a reflector (shading normal
// from the mesh normals, no normal map: the built-in scenes have none).
Ray mirrorRay(const BenchScene& b, const Ray& ray, const RTCRayHit& h, float epsilon) {
  const int instance = int(h.hit.geomID);
  const Mesh& mesh = b.scene.meshes[size_t(b.scene.instances[size_t(instance)].mesh)];
  const RayScene& rs = b.tracer->rayScene();
  const uvec3 tri = mesh.triangles[h.hit.primID];
  const auto& world = rs.worldPositions(instance);
  const float w0 = 1.0f - h.hit.u - h.hit.v, w1 = h.hit.u, w2 = h.hit.v;
  const vec3 p = w0 * world[tri.x] + w1 * world[tri.y] + w2 * world[tri.z];
  const vec3 ng =
      glm::normalize(glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]));
  vec3 n = ng;
  if (!mesh.normals.empty())
    n = glm::normalize(
        rs.normalMatrixOf(instance) *
        (w0 * mesh.normals[tri.x] + w1 * mesh.normals[tri.y] + w2 * mesh.normals[tri.z]));
  const vec3 facing = shading::facing_normal(n, ng, -ray.direction);
  const vec3 r = shading::reflect_direction(ray.direction, facing);
  const vec3 side = glm::dot(ng, r) >= 0.0f ? ng : -ng;
  return Ray{p + side * epsilon, r, 0.0f, kInfinity};
}

void traceAll(RTCScene scene, const std::vector<Ray>& rays, std::vector<RTCRayHit>& hits) {
  hits.resize(rays.size());
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (size_t i = 0; i < rays.size(); ++i) {
    hits[i] = toRtcRayHit(rays[i]);
    rtcIntersect1(scene, &context, &hits[i]);
  }
}

std::unique_ptr<BenchScene> makeBenchScene(const std::string& name) {
  auto b = std::make_unique<BenchScene>();
  b->name = name;
  b->scene = makeBuiltinScene(name);
  b->environment = EnvironmentMap::forScene(b->scene);
  b->tracer = std::make_unique<RayTracer>(b->scene, b->environment);
  b->tracer->prepare(0.0f);
  b->view = View(b->scene.camera(), kSize);
  for (int y = 0; y < kSize.y; ++y)
    for (int x = 0; x < kSize.x; ++x)
      b->primary.push_back(b->view.primaryRay(float(x) + 0.5f, float(y) + 0.5f));
  traceAll(b->rtc(), b->primary, b->primary_hits);

  const float epsilon = 1e-5f * std::max(b->scene.bounds().radius(), 1e-3f);
  for (int ty = 0; ty < kSize.y; ty += kTile)
    for (int tx = 0; tx < kSize.x; tx += kTile)
      for (int y = ty; y < ty + kTile; ++y)
        for (int x = tx; x < tx + kTile; ++x) {
          const size_t i = size_t(y) * size_t(kSize.x) + size_t(x);
          const RTCRayHit& h = b->primary_hits[i];
          if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
          const Instance& inst = b->scene.instances[h.hit.geomID];
          if (!b->scene.materials[size_t(inst.material)].isReflector()) continue;
          b->reflected.push_back(mirrorRay(*b, b->primary[i], h, epsilon));
        }
  traceAll(b->rtc(), b->reflected, b->reflected_hits);
  return b;
}

}  // namespace

const std::vector<std::string>& benchSceneNames() {
  static const std::vector<std::string> names = {"sphere-over-checker", "spheres9"};
  return names;
}

const BenchScene& benchScene(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<BenchScene>> scenes;
  std::lock_guard lock(mutex);
  auto& slot = scenes[name];
  if (!slot) slot = makeBenchScene(name);
  return *slot;
}

int hardwareThreads() {
  return std::max(1, int(tbb::this_task_arena::max_concurrency()));
}

std::vector<int> threadCounts() {
  int n = hardwareThreads();
  return n > 1 ? std::vector<int>{1, n} : std::vector<int>{1};
}

bool sameHit(const RTCRayHit& a, const RTCRayHit& b) {
  if (a.hit.geomID != b.hit.geomID) return false;
  if (a.hit.geomID == RTC_INVALID_GEOMETRY_ID) return true;
  return a.hit.primID == b.hit.primID &&
         std::memcmp(&a.ray.tfar, &b.ray.tfar, sizeof(float)) == 0 &&
         std::memcmp(&a.hit.u, &b.hit.u, sizeof(float)) == 0 &&
         std::memcmp(&a.hit.v, &b.hit.v, sizeof(float)) == 0;
}

}  // namespace mirage::bench
