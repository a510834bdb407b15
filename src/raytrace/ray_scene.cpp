#include "raytrace/ray_scene.h"

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
}  // namespace

RayScene::RayScene(const Scene& scene) : scene_(scene) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throwRuntime("Embree: cannot create a device (error {})", int(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, errorCallback, nullptr);
}

RayScene::~RayScene() {
  if (rtc_scene_) rtcReleaseScene(rtc_scene_);
  rtcReleaseDevice(device_);
}

double RayScene::build(float time) {
  Stopwatch watch;
  if (rtc_scene_) rtcReleaseScene(rtc_scene_);
  rtc_scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(rtc_scene_, RTC_BUILD_QUALITY_HIGH);
  matrices_.resize(scene_.instances.size());
  world_.resize(scene_.instances.size());
  for (size_t i = 0; i < scene_.instances.size(); ++i) {
    const Instance& inst = scene_.instances[i];
    const Mesh& mesh = scene_.meshes[size_t(inst.mesh)];
    matrices_[i] = inst.matrixAt(time);
    auto& world = world_[i];
    world.resize(mesh.positions.size());
    for (size_t v = 0; v < world.size(); ++v) world[v] = transformPoint(matrices_[i], mesh.positions[v]);

    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree may read 16 bytes at the last vertex: share a padded copy.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(vec3), world.size()));
    std::memcpy(vertices, world.data(), world.size() * sizeof(vec3));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(uvec3), mesh.triangles.size()));
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

RayHit RayScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = ray.origin.x;
  rh.ray.org_y = ray.origin.y;
  rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.direction.x;
  rh.ray.dir_y = ray.direction.y;
  rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = ray.tmin;
  rh.ray.tfar = ray.tmax;
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtc_scene_, &context, &rh);
  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = rh.ray.tfar;
  hit.instance = int(rh.hit.geomID);
  hit.primitive = rh.hit.primID;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  return hit;
}

}  // namespace mirage
