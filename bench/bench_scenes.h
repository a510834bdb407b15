// What the micro-benchmarks share: the built-in scenes ready to trace (BVH, view, environment)
// with the rays they trace computed once per process, Embree ray/packet helpers, and a way to
// run tile loops on a chosen number of threads.
#pragma once

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <memory>
#include <string>
#include <vector>

#include "raytrace/embree_rays.h"
#include "raytrace/tracer.h"
#include "scene/environment.h"
#include "scene/scene.h"

namespace mirage::bench {

inline constexpr ivec2 kSize{720, 512};  // the size of every ray benchmark (multiple of 16)
inline constexpr int kTile = 16;         // the tracer's tile

struct BenchScene {
  std::string name;
  Scene scene;
  EnvironmentMap environment;
  std::unique_ptr<RayTracer> tracer;    // BVH built at time 0
  View view;                            // the scene's first camera at kSize
  std::vector<Ray> primary;             // pixel-centre rays, row-major
  std::vector<RTCRayHit> primary_hits;  // rtcIntersect1's answers for `primary`
  // The mirror reflections of the primary hits on reflectors, in the tracer's order (16x16
  // tiles row-major, pixels row-major in a tile), offset along the geometric normal.
  std::vector<Ray> reflected;
  std::vector<RTCRayHit> reflected_hits;

  RTCScene rtc() const { return tracer->rayScene().handle(); }
};

// The scenes every ray benchmark runs on.
const std::vector<std::string>& benchSceneNames();
// Built on first use and kept for the process (building spheres9's BVH takes a while).
const BenchScene& benchScene(const std::string& name);

int hardwareThreads();
// The thread counts benchmarks run with: 1 and all of them (once if the machine has one).
std::vector<int> threadCounts();

// Same hit, bit for bit (instance, triangle, t, u, v); two misses are the same.
bool sameHit(const RTCRayHit& a, const RTCRayHit& b);

// Runs body(begin, end) over [0, count) in chunks of `grain`, on `threads` threads.
template <typename F>
void forChunks(int count, int grain, int threads, const F& body) {
  if (threads == 1) {
    for (int b = 0; b < count; b += grain) body(b, std::min(b + grain, count));
    return;
  }
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, count, grain), [&](const auto& r) {
      for (int b = r.begin(); b < r.end(); b += grain) body(b, std::min(b + grain, r.end()));
    });
  });
}

// Embree's packet types by width.
template <int K>
struct Packet;
template <>
struct Packet<4> {
  using Type = RTCRayHit4;
  static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, Type* p) {
    rtcIntersect4(valid, s, c, p);
  }
};
template <>
struct Packet<8> {
  using Type = RTCRayHit8;
  static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, Type* p) {
    rtcIntersect8(valid, s, c, p);
  }
};
template <>
struct Packet<16> {
  using Type = RTCRayHit16;
  static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, Type* p) {
    rtcIntersect16(valid, s, c, p);
  }
};

}  // namespace mirage::bench
