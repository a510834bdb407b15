// The top-level "probes" of the scene format (docs/scene-format.md): reflection probes placed as
// an engine places them (scene/probes.h). Checked for shape, types and ranges here; which
// reflectors they influence is checked once the scene is whole (probeWarnings).
#include <fmt/format.h>

#include "scene/scene_json_internal.h"

namespace mirage::scene_json {

namespace {

// Probes past this many would not fit a cube-map array of useful size on every driver.
constexpr int kMaxProbes = 32;
// Positions and sizes, in scene units.
const Range kCoordinate = Range::closed(-1e6, 1e6);
const Range kSize = Range{0.0, 1e6, true, false};

std::string vectorText(const vec3& v) { return fmt::format("[{:g}, {:g}, {:g}]", v.x, v.y, v.z); }

// {"box": {"min": [x, y, z], "max": [x, y, z]}}, {"box": {"size": [x, y, z]}} (centred at the
// probe) or {"sphere": radius} (about the probe).
ProbeVolume parseVolume(const Field& f, const vec3& position) {
  f.requireObject("a probe volume");
  f.allowKeys({"box", "sphere"}, "a probe volume");
  ProbeVolume v;
  if (f.has("box") == f.has("sphere")) f.fail("needs exactly one of \"box\" and \"sphere\"");
  if (auto sphere = f.optional("sphere")) {
    v.sphere = true;
    v.centre = position;
    v.radius = sphere->number(kSize);
    return v;
  }
  const Field box = f.required("box");
  box.requireObject("a probe box");
  box.allowKeys({"min", "max", "size"}, "a probe box");
  if (auto size = box.optional("size")) {
    if (box.has("min") || box.has("max")) box.fail("has \"size\" and \"min\"/\"max\": give one");
    const vec3 half = 0.5f * size->vector3(kSize);
    v.box = Bounds3{position - half, position + half};
    return v;
  }
  v.box.lo = box.required("min").vector3(kCoordinate);
  v.box.hi = box.required("max").vector3(kCoordinate);
  for (int a = 0; a < 3; ++a)
    if (!(v.box.lo[a] < v.box.hi[a]))
      box.required("max").fail("= {}: must exceed min = {} on every axis", vectorText(v.box.hi),
                               vectorText(v.box.lo));
  return v;
}

// Half the smallest extent of the volume: the deepest point inside it.
float deepest(const ProbeVolume& v) {
  if (v.sphere) return v.radius;
  const vec3 e = v.box.extent();
  return 0.5f * std::min(std::min(e.x, e.y), e.z);
}

ReflectionProbe parseProbe(const Field& f, size_t index) {
  f.allowKeys({"name", "position", "influence", "blend_distance", "proxy", "priority"},
              "a probe");
  ReflectionProbe p;
  p.where = f.where();
  p.name = f.stringOr("name", fmt::format("probe-{}", index + 1));
  p.position = f.required("position").vector3(kCoordinate);
  p.influence = parseVolume(f.required("influence"), p.position);
  p.blend_distance =
      f.numberOr("blend_distance", 0.0f, Range::closed(0.0, double(deepest(p.influence))));
  if (auto proxy = f.optional("proxy")) {
    p.proxy = parseVolume(*proxy, p.position);
    if (!p.proxy.contains(p.position))
      proxy->fail("does not hold the probe's position {}: its parallax is corrected from there",
                  vectorText(p.position));
  } else {
    p.proxy = p.influence;
    if (!p.proxy.contains(p.position))
      f.required("influence")
          .fail("does not hold the probe's position {} and no \"proxy\" is given (the influence "
                "is the proxy then, and the proxy must hold the position)",
                vectorText(p.position));
  }
  p.priority = f.integerOr("priority", 0, -1000, 1000);
  return p;
}

}  // namespace

std::vector<ReflectionProbe> parseProbes(const Field& list) {
  std::vector<ReflectionProbe> probes;
  const std::vector<Field> items = list.items();
  if (int(items.size()) > kMaxProbes)
    list.fail("has {} probes; at most {} are allowed", items.size(), kMaxProbes);
  for (size_t i = 0; i < items.size(); ++i) {
    ReflectionProbe p = parseProbe(items[i], i);
    for (const ReflectionProbe& other : probes)
      if (other.name == p.name)
        items[i].required("name").fail("= {} is already the name of another probe",
                                       shortQuote(p.name));
    probes.push_back(std::move(p));
  }
  return probes;
}

}  // namespace mirage::scene_json
