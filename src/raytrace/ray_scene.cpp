#include "raytrace/ray_scene.h"

#include "raytrace/embree_rays.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "core/timer.h"

namespace mirage {

namespace {
// Embree calls this from inside its own code: never throw through it, report after the call.
void errorCallback(void*, RTCError code, const char* message) {
  spdlog::error("Embree error {}: {}", int(code), message ? message : "");
}
RayHit toRayHit(const RTCRayHit& rh) {
  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = rh.ray.tfar;
  hit.instance = int(rh.hit.geomID);
  hit.primitive = rh.hit.primID;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  return hit;
}

}  // namespace

RayScene::RayScene(const Scene& scene) : scene_(scene) {
  // MIRAGE_EMBREE_CONFIG (e.g. "isa=avx2", "threads=1") lets tests and benchmarks pin Embree's
  // kernels: packet and single-ray results are compared per ISA.
  const char* config = std::getenv("MIRAGE_EMBREE_CONFIG");
  device_ = rtcNewDevice(config);
  if (!device_)
    throwRuntime("Embree: cannot create a device (error {})", int(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, errorCallback, nullptr);
}

RayScene::~RayScene() {
  if (rtc_scene_) rtcReleaseScene(rtc_scene_);
  rtcReleaseDevice(device_);
}

bool RayScene::sameGeometryAt(float time) const {
  if (!rtc_scene_) return false;
  if (time == time_) return true;
  for (size_t i = 0; i < scene_.instances.size(); ++i) {
    const Instance& inst = scene_.instances[i];
    if (inst.matrixAt(time) != matrices_[i]) return false;
    if (inst.deforms() && inst.deformation.period() > 0.0f) return false;
  }
  return true;
}

double RayScene::build(float time) {
  // A frame where only the light moved keeps the BVH.
  if (sameGeometryAt(time)) {
    light_ = scene_.lightAt(time);
    time_ = time;
    return 0.0;
  }
  Stopwatch watch;
  if (rtc_scene_) rtcReleaseScene(rtc_scene_);
  rtc_scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(rtc_scene_, RTC_BUILD_QUALITY_HIGH);
  matrices_.resize(scene_.instances.size());
  normal_matrices_.resize(scene_.instances.size());
  linear_parts_.resize(scene_.instances.size());
  world_.resize(scene_.instances.size());
  deformed_.resize(scene_.instances.size());
  light_ = scene_.lightAt(time);
  for (size_t i = 0; i < scene_.instances.size(); ++i) {
    const Instance& inst = scene_.instances[i];
    if (inst.deforms()) scene_.meshAt(int(i), time, deformed_[i]);
    const Mesh& mesh = inst.deforms() ? deformed_[i] : scene_.meshes[size_t(inst.mesh)];
    matrices_[i] = inst.matrixAt(time);
    normal_matrices_[i] = normalMatrix(matrices_[i]);
    linear_parts_[i] = mat3(matrices_[i]);
    auto& world = world_[i];
    world.resize(mesh.positions.size());
    for (size_t v = 0; v < world.size(); ++v)
      world[v] = transformPoint(matrices_[i], mesh.positions[v]);

    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree may read 16 bytes at the last vertex: share a padded copy.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(vec3), world.size()));
    std::memcpy(vertices, world.data(), world.size() * sizeof(vec3));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(uvec3),
                                mesh.triangles.size()));
    std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * sizeof(uvec3));
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(rtc_scene_, geometry, unsigned(i));
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(rtc_scene_);
  if (RTCError error = rtcGetDeviceError(device_); error != RTC_ERROR_NONE)
    throwRuntime("Embree could not build the scene (error {})", int(error));
  time_ = time;
  return watch.ms();
}

const Mesh& RayScene::mesh(int instance) const {
  const Instance& inst = scene_.instances[size_t(instance)];
  return inst.deforms() ? deformed_[size_t(instance)] : scene_.meshes[size_t(inst.mesh)];
}

RayHit RayScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh = toRtcRayHit(ray);
  rtcIntersect1(rtc_scene_, &context, &rh);
  return toRayHit(rh);
}

// rtcIntersect16 with the *incoherent* context flag: Embree 3.13's hybrid packet intersector
// then runs its single-ray traversal and triangle test on each ray of the packet (the code
// rtcIntersect1 runs), so every hit is rtcIntersect1's, bit for bit, while the packet saves the
// per-call overhead and sets the rays up 16 wide. The coherent flag would switch to frustum
// traversal with packet triangle tests, which give other hits on edges and ties
// (docs/benchmarks.md measures both; tests/raytrace checks render() against single rays).
void RayScene::intersect(const Ray* rays, RayHit* hits, size_t n) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  for (size_t begin = 0; begin < n; begin += 16) {
    const int count = int(std::min<size_t>(16, n - begin));
    alignas(64) RTCRayHit16 packet;
    alignas(64) int valid[16];
    for (int k = 0; k < 16; ++k) {
      const Ray& ray = rays[begin + size_t(std::min(k, count - 1))];
      valid[k] = k < count ? -1 : 0;
      setPacketLane(packet, k, ray);
    }
    rtcIntersect16(valid, rtc_scene_, &context, &packet);
    for (int k = 0; k < count; ++k) hits[begin + size_t(k)] = toRayHit(packetLaneHit(packet, k));
  }
}

}  // namespace mirage
