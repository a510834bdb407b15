#include "methods/impostor/impostor_groups.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <queue>

#include "core/error.h"
#include "gpu/gl.h"

namespace mirage {

namespace {

bool moves(const Scene& scene, int instance) {
  const Instance& i = scene.instances[size_t(instance)];
  return !i.animation.empty() || i.deforms();
}

Bounds3 unionBounds(const Scene& scene, const std::vector<int>& members) {
  Bounds3 b;
  for (int m : members) b.extend(scene.instanceBounds(m, 0.0f));
  return b;
}

// How large a cluster looks from the nearest reflector: its bounding radius over its distance
// (a cluster without reflectors is ranked by its radius alone).
float apparentSize(const Bounds3& b, const std::vector<BoundingSphere>& reflectors) {
  const float radius = b.radius();
  if (reflectors.empty()) return radius;
  float nearest = INFINITY;
  for (const BoundingSphere& r : reflectors)
    nearest = std::min(nearest, glm::length(r.centre - b.center()));
  return radius / std::max(nearest, radius);
}

// Whether a cluster's bounding sphere meets a reflector's: its one billboard, through its
// centre, would stand beside the reflector, and the members next to it would vanish from the
// rays that leave the reflector along the billboard's plane or away from it.
bool meetsAReflector(const Bounds3& b, const std::vector<BoundingSphere>& reflectors) {
  for (const BoundingSphere& r : reflectors)
    if (glm::length(r.centre - b.center()) <= b.radius() + r.radius) return true;
  return false;
}

struct Cluster {
  std::vector<int> members;
  Bounds3 bounds;
  float size = 0.0f;  // the split order: meeting a reflector first (2), then the apparent size
  bool straddles = false;
};

// Splits a cluster of two or more at the median of its members' centres along their longest
// axis (ties by instance, so that the split is the same on every machine).
std::pair<std::vector<int>, std::vector<int>> split(const Scene& scene,
                                                    const std::vector<int>& members) {
  std::vector<std::pair<vec3, int>> centred;
  Bounds3 centres;
  for (int m : members) {
    const vec3 c = scene.instanceBounds(m, 0.0f).center();
    centred.emplace_back(c, m);
    centres.extend(c);
  }
  const vec3 e = centres.extent();
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  std::sort(centred.begin(), centred.end(), [axis](const auto& a, const auto& b) {
    return a.first[axis] != b.first[axis] ? a.first[axis] < b.first[axis] : a.second < b.second;
  });
  const size_t half = centred.size() / 2;
  std::vector<int> lo, hi;
  for (size_t k = 0; k < centred.size(); ++k) (k < half ? lo : hi).push_back(centred[k].second);
  std::sort(lo.begin(), lo.end());
  std::sort(hi.begin(), hi.end());
  return {lo, hi};
}

std::vector<ImpostorGroup> toGroups(std::vector<Cluster> clusters) {
  std::sort(clusters.begin(), clusters.end(), [](const Cluster& a, const Cluster& b) {
    return a.members.front() < b.members.front();
  });
  std::vector<ImpostorGroup> groups;
  for (Cluster& c : clusters) groups.push_back({std::move(c.members), c.bounds});
  return groups;
}

}  // namespace

GroupSetting parseGroupSetting(const std::string& text, const std::string& option) {
  if (text == "auto") return {GroupSetting::Mode::kAuto, 0};
  if (text == "per-object") return {GroupSetting::Mode::kPerObject, 0};
  int count = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, count);
  if (text.empty() || ec != std::errc() || ptr != end || count < 1 || count > kMaxGroupCount)
    throwInput("{} '{}' is not allowed (allowed: auto, per-object, or a group count 1..{})", option,
               text, kMaxGroupCount);
  return {GroupSetting::Mode::kCount, count};
}

std::string groupSettingText(const GroupSetting& setting) {
  switch (setting.mode) {
    case GroupSetting::Mode::kAuto:
      return "auto";
    case GroupSetting::Mode::kPerObject:
      return "per-object";
    case GroupSetting::Mode::kCount:
      break;
  }
  return std::to_string(setting.count);
}

std::vector<ImpostorGroup> singletonGroups(const Scene& scene, const std::vector<int>& objects) {
  std::vector<Cluster> clusters;
  for (int i : objects) clusters.push_back({{i}, scene.instanceBounds(i, 0.0f), 0.0f});
  return toGroups(std::move(clusters));
}

std::vector<ImpostorGroup> clusterObjects(const Scene& scene, const std::vector<int>& objects,
                                          int target, int most) {
  std::vector<BoundingSphere> reflectors;
  for (int r : scene.reflectorInstances()) {
    const Bounds3 b = scene.instanceBounds(r);
    reflectors.push_back({b.center(), b.radius()});
  }
  std::vector<Cluster> done;
  std::vector<int> still;
  for (int i : objects)
    if (moves(scene, i))
      done.push_back({{i}, scene.instanceBounds(i, 0.0f), 0.0f});
    else
      still.push_back(i);
  if (still.empty()) return toGroups(std::move(done));
  std::sort(still.begin(), still.end());
  auto make = [&](std::vector<int> members) {
    Cluster c{std::move(members), {}, 0.0f, false};
    c.bounds = unionBounds(scene, c.members);
    c.straddles = c.members.size() > 1 && meetsAReflector(c.bounds, reflectors);
    c.size = c.members.size() < 2 ? -1.0f
                                  : (c.straddles ? 2.0f : apparentSize(c.bounds, reflectors));
    return c;
  };
  // Largest apparent size first; among equals the lowest first member (determinism).
  auto smaller = [](const Cluster& a, const Cluster& b) {
    return a.size != b.size ? a.size < b.size : a.members.front() > b.members.front();
  };
  std::priority_queue<Cluster, std::vector<Cluster>, decltype(smaller)> queue(smaller);
  queue.push(make(still));
  // To the count asked, then on while a group meets a reflector, up to `most`.
  const auto more = [&] {
    const int count = int(done.size() + queue.size());
    return count < target || (count < most && queue.top().straddles);
  };
  while (more() && queue.top().members.size() > 1) {
    Cluster c = queue.top();
    queue.pop();
    auto [lo, hi] = split(scene, c.members);
    queue.push(make(std::move(lo)));
    queue.push(make(std::move(hi)));
  }
  for (; !queue.empty(); queue.pop()) done.push_back(queue.top());
  return toGroups(std::move(done));
}

int groupsThatFit(const GroupCost& cost, const GroupCaps& caps, std::string* limit) {
  auto fits = [&](int g) {
    return cost.layers(g) <= caps.max_layers && cost.bytes(g) <= caps.max_bytes;
  };
  if (!fits(1)) {
    if (limit) *limit = cost.layers(1) > caps.max_layers ? "texture layers" : "memory";
    return 0;
  }
  int64_t by_layers = cost.layers_per_group > 0
                          ? (caps.max_layers - cost.fixed_layers) / cost.layers_per_group
                          : int64_t(kMaxGroupCount);
  int64_t by_bytes = cost.bytes_per_group > 0
                         ? int64_t((caps.max_bytes - cost.fixed_bytes) / cost.bytes_per_group)
                         : int64_t(kMaxGroupCount);
  const int64_t fit = std::min({by_layers, by_bytes, int64_t(caps.max_groups)});
  if (limit)
    *limit =
        fit == by_layers ? "texture layers" : (fit == by_bytes ? "memory" : "groups per reflector");
  return int(fit);
}

Grouping chooseGroups(const Scene& scene, const std::vector<int>& objects,
                      const GroupSetting& setting, const GroupCost& cost, const GroupCaps& caps,
                      const std::string& method, const std::string& shrink_hint) {
  Grouping g;
  g.objects = int(objects.size());
  g.fit = groupsThatFit(cost, caps, &g.limit);
  // What the method needs whatever its groups, beyond --impostor-memory: a setting of the user's
  // that cannot be met (bad input), not a driver limit.
  const auto mib = [](uint64_t bytes) { return (bytes + (1u << 20) - 1) >> 20; };
  const int least = objects.empty() ? 0 : 1;
  if (cost.bytes(least) > caps.max_bytes)
    throwInput(
        "{}: --impostor-memory {} (MiB) cannot be met: {} need at least {} MiB on this scene "
        "(allowed: 16..1048576)",
        method, caps.max_bytes >> 20, least ? "one impostor group and the fixed textures" :
                                              "the fixed textures", mib(cost.bytes(least)));
  if (objects.empty()) return g;
  if (g.fit == 0)
    throwGpu(
        "{}: even one impostor group needs {} texture layers, beyond the driver's "
        "GL_MAX_ARRAY_TEXTURE_LAYERS ({}); {} would fit",
        method, cost.layers(1), caps.max_layers, shrink_hint);
  // A group that meets a reflector is split beyond the count, as far as the storage allows (the
  // driver's layers and the memory cap; not the groups-per-reflector cap, a cost).
  GroupCaps storage = caps;
  storage.max_groups = kMaxGroupCount;
  const int most = std::max(groupsThatFit(cost, storage), 1);
  switch (setting.mode) {
    case GroupSetting::Mode::kPerObject:
      g.groups = singletonGroups(scene, objects);
      break;
    case GroupSetting::Mode::kCount:
      g.groups = clusterObjects(scene, objects, setting.count, std::max(most, setting.count));
      break;
    case GroupSetting::Mode::kAuto:
      g.groups = int(objects.size()) <= g.fit ? singletonGroups(scene, objects)
                                              : clusterObjects(scene, objects, g.fit, most);
      break;
  }
  const int count = int(g.groups.size());
  g.layers = cost.layers(count);
  g.bytes = cost.bytes(count);
  // auto makes more groups than fit only when more objects move than fit (they stay apart).
  if (g.layers > caps.max_layers && setting.mode == GroupSetting::Mode::kAuto)
    throwGpu(
        "{}: {} groups of {} objects (moving objects are never merged) need {} texture layers, "
        "beyond the driver's GL_MAX_ARRAY_TEXTURE_LAYERS ({}); at most {} groups fit",
        method, count, g.objects, g.layers, caps.max_layers, g.fit);
  if (g.layers > caps.max_layers)
    throwGpu(
        "{}: --impostor-groups {} makes {} groups of {} objects, needing {} texture layers, beyond "
        "the driver's GL_MAX_ARRAY_TEXTURE_LAYERS ({}); --impostor-groups auto ({} groups) would "
        "fit",
        method, groupSettingText(setting), count, g.objects, g.layers, caps.max_layers,
        std::min(g.fit, g.objects));
  if (g.bytes > caps.max_bytes)
    throwInput(
        "{}: --impostor-groups {} makes {} groups of {} objects, needing {} MiB, beyond "
        "--impostor-memory {} (MiB); --impostor-groups auto ({} groups) or --impostor-memory {} "
        "would fit",
        method, groupSettingText(setting), count, g.objects, mib(g.bytes), caps.max_bytes >> 20,
        std::min(g.fit, g.objects), mib(g.bytes));
  return g;
}

std::vector<std::vector<int>> Grouping::memberLists() const {
  std::vector<std::vector<int>> lists;
  for (const ImpostorGroup& g : groups) lists.push_back(g.members);
  return lists;
}

int64_t driverArrayLayers() {
  GLint layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  return layers;
}

}  // namespace mirage
