// Conversions between mirage's rays/hits and Embree's single-ray and packet layouts, shared by
// the tracer's RayScene and the micro-benchmarks that compare Embree's kernels.
#pragma once

#include <embree3/rtcore.h>

#include "core/ray.h"

namespace mirage {

// A ray ready for rtcIntersect1: the full interval, every mask bit, no hit yet.
inline RTCRayHit toRtcRayHit(const Ray& ray) {
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
  return rh;
}

// Lane k of an RTCRayHit4/8/16 packet set up as toRtcRayHit sets up a single ray.
template <typename Packet>
void setPacketLane(Packet& p, int k, const Ray& ray) {
  p.ray.org_x[k] = ray.origin.x;
  p.ray.org_y[k] = ray.origin.y;
  p.ray.org_z[k] = ray.origin.z;
  p.ray.dir_x[k] = ray.direction.x;
  p.ray.dir_y[k] = ray.direction.y;
  p.ray.dir_z[k] = ray.direction.z;
  p.ray.tnear[k] = ray.tmin;
  p.ray.tfar[k] = ray.tmax;
  p.ray.time[k] = 0.0f;
  p.ray.mask[k] = 0xffffffffu;
  p.ray.id[k] = 0;
  p.ray.flags[k] = 0;
  p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

// Lane k's answer as a single RTCRayHit (distance and hit fields only).
template <typename Packet>
RTCRayHit packetLaneHit(const Packet& p, int k) {
  RTCRayHit h{};
  h.ray.tfar = p.ray.tfar[k];
  h.hit.geomID = p.hit.geomID[k];
  h.hit.primID = p.hit.primID[k];
  h.hit.u = p.hit.u[k];
  h.hit.v = p.hit.v[k];
  return h;
}

}  // namespace mirage
