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

// Whether the instance's triangles can change over time (a light's motion moves none).
bool moves(const Instance& inst) {
  return inst.deforms() || !inst.animation.empty();
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
  for (RTCGeometry geometry : geometries_) rtcReleaseGeometry(geometry);
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
  const size_t n = scene_.instances.size();
  // One Embree scene and one geometry per instance for the RayScene's life: later builds write
  // the moved instances' vertices into the geometry's own buffer and commit again.
  //
  // A scene where something moves is two-level (scene quality LOW: a small top BVH over one BVH
  // per geometry), so a commit rebuilds only the geometries that changed: the still ones keep
  // the high-quality BVH of the first build, and the animated or deforming ones are refitted —
  // their vertices move, their triangles and the tree's topology stay. At 720x512 this cut the
  // per-frame update of mirror-room from 6.8 to 0.7 ms and of spheres9 from 66 to 16 ms
  // (docs/benchmarks.md, "BVH builds"). A still scene is built once, as one flat high-quality BVH:
  // reflected rays leaving a sphere over a floor trace 8% faster in it than in the two-level one.
  const bool first = rtc_scene_ == nullptr;
  if (first) {
    rtc_scene_ = rtcNewScene(device_);
    const bool any_moves = std::any_of(scene_.instances.begin(), scene_.instances.end(), moves);
    rtcSetSceneBuildQuality(rtc_scene_, any_moves ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_HIGH);
    geometries_.assign(n, nullptr);
    matrices_.resize(n);
    normal_matrices_.resize(n);
    linear_parts_.resize(n);
    world_.resize(n);
    deformed_.resize(n);
  }
  light_ = scene_.lightAt(time);
  for (size_t i = 0; i < n; ++i) {
    const Instance& inst = scene_.instances[i];
    const mat4 matrix = inst.matrixAt(time);
    if (!first && !inst.deforms() && matrix == matrices_[i]) continue;  // this one stood still
    if (inst.deforms()) scene_.meshAt(int(i), time, deformed_[i]);
    const Mesh& mesh = inst.deforms() ? deformed_[i] : scene_.meshes[size_t(inst.mesh)];
    matrices_[i] = matrix;
    normal_matrices_[i] = normalMatrix(matrix);
    linear_parts_[i] = mat3(matrix);
    auto& world = world_[i];
    world.resize(mesh.positions.size());
    for (size_t v = 0; v < world.size(); ++v) world[v] = transformPoint(matrix, mesh.positions[v]);

    if (first) {
      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      // Embree may read 16 bytes past the last vertex: its own buffers are padded for that.
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(vec3),
                              world.size());
      auto* indices = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                  sizeof(uvec3), mesh.triangles.size()));
      std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * sizeof(uvec3));
      // Only read in a two-level scene (above).
      rtcSetGeometryBuildQuality(geometry,
                                 moves(inst) ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_HIGH);
      rtcAttachGeometryByID(rtc_scene_, geometry, unsigned(i));
      geometries_[i] = geometry;  // the scene holds it too; released in the destructor
    }
    RTCGeometry geometry = geometries_[i];
    // A deformation moves vertices and keeps the topology, so the sizes never change.
    std::memcpy(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0), world.data(),
                world.size() * sizeof(vec3));
    rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(geometry);
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
