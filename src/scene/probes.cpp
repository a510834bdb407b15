#include "scene/probes.h"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "scene/scene.h"

namespace mirage {

bool ProbeVolume::contains(const vec3& p) const {
  return sphere ? glm::length(p - centre) <= radius : box.contains(p);
}

float ProbeVolume::volume() const {
  if (sphere) return 4.0f / 3.0f * kPi * radius * radius * radius;
  const vec3 e = box.extent();
  return e.x * e.y * e.z;
}

std::vector<int> probeBlendOrder(const std::vector<ReflectionProbe>& probes) {
  std::vector<int> order(probes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const ReflectionProbe &pa = probes[size_t(a)], &pb = probes[size_t(b)];
    if (pa.priority != pb.priority) return pa.priority > pb.priority;
    return pa.influence.volume() < pb.influence.volume();
  });
  return order;
}

namespace {

// Whether the box meets the volume (a sphere: its closest point to the centre is within it).
bool meets(const ProbeVolume& volume, const Bounds3& b) {
  if (volume.sphere) {
    const vec3 closest = glm::clamp(volume.centre, b.lo, b.hi);
    return glm::length(closest - volume.centre) <= volume.radius;
  }
  const Bounds3& v = volume.box;
  return b.lo.x <= v.hi.x && b.hi.x >= v.lo.x && b.lo.y <= v.hi.y && b.hi.y >= v.lo.y &&
         b.lo.z <= v.hi.z && b.hi.z >= v.lo.z;
}

}  // namespace

std::vector<int> reflectorsInfluenced(const Scene& scene, const ReflectionProbe& probe) {
  std::vector<int> out;
  for (int r : scene.reflectorInstances())
    if (meets(probe.influence, scene.instanceBounds(r))) out.push_back(r);
  return out;
}

std::vector<int> shownByReflectionProbe(const Scene& scene, const ReflectionProbe& probe,
                                        const std::function<Bounds3(int)>& instance_bounds) {
  std::vector<int> out;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (!scene.isReflector(int(i)) || !instance_bounds(int(i)).contains(probe.position))
      out.push_back(int(i));
  return out;
}

std::vector<std::string> probeWarnings(const Scene& scene) {
  std::vector<std::string> out;
  if (scene.probes.empty()) return out;
  std::vector<bool> covered(scene.instances.size(), false);
  for (const ReflectionProbe& probe : scene.probes) {
    const std::vector<int> influenced = reflectorsInfluenced(scene, probe);
    if (influenced.empty())
      out.push_back(fmt::format("{} ('{}') influences no reflector: it is captured for nothing",
                                probe.where, probe.name));
    for (int r : influenced) covered[size_t(r)] = true;
  }
  for (int r : scene.reflectorInstances())
    if (!covered[size_t(r)])
      out.push_back(
          fmt::format("{}: reflector '{}' is in no probe's influence volume: it shows the distant "
                      "environment only",
                      scene.source, scene.instances[size_t(r)].name));
  return out;
}

}  // namespace mirage
