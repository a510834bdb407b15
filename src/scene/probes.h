// A scene's reflection probes as an engine ships them (a scene file's "probes",
// docs/scene-format.md): each captured at a position, influencing the reflector points inside its
// volume (a box or a sphere) with a blend distance inside the volume's surface, looked up through
// a proxy of its own (by default its influence volume), ordered by a priority. Where a scene
// gives none, the probe methods keep one probe at each reflector, its own (methods.md, envmap).
// How overlapping probes share a point: shading/probe_blend.h.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/bounds.h"

namespace mirage {

struct Scene;

// A box, or a sphere of `radius` about `centre`.
struct ProbeVolume {
  bool sphere = false;
  Bounds3 box;
  vec3 centre{0.0f};
  float radius = 0.0f;

  bool contains(const vec3& p) const;
  float volume() const;
};

struct ReflectionProbe {
  std::string name;
  std::string where;  // "file: probes[i]", for messages
  vec3 position{0.0f};
  ProbeVolume influence;
  float blend_distance = 0.0f;  // in [0, half the influence's smallest extent]
  ProbeVolume proxy;            // holds `position`
  int priority = 0;             // higher first
};

// The order in which a point's probes take their shares: priority, highest first; then the
// smaller influence volume first (a small probe inside a large one shows its corner of the room);
// then scene order.
std::vector<int> probeBlendOrder(const std::vector<ReflectionProbe>& probes);

// The reflector instances whose bounds meet the probe's influence volume.
std::vector<int> reflectorsInfluenced(const Scene& scene, const ReflectionProbe& probe);

// What a probe shows: every diffuse instance, and every reflector but those whose bounds hold the
// probe's position (a probe captured inside an object sees its inside). `instance_bounds` gives an
// instance's world bounds at the capture's time (GpuScene::instanceBounds: the scene moves).
std::vector<int> shownByReflectionProbe(const Scene& scene, const ReflectionProbe& probe,
                                        const std::function<Bounds3(int)>& instance_bounds);

// Warnings for probes that influence no reflector, and reflectors that no probe influences (they
// see the distant environment only).
std::vector<std::string> probeWarnings(const Scene& scene);

}  // namespace mirage
