// Impostor groups: the diffuse objects an impostor method stands in for, clustered so that one
// billboard (per reflector) or one set of depth maps covers a whole group. Real assets have
// hundreds of parts, and per-object impostors grow with objects x reflectors past what a driver
// holds (its texture layers) and what a user will spend (memory); a group merges small or
// distant objects, and a reflected ray tests one impostor where it tested many.
//
// The clustering is top-down and deterministic: every still object starts in one cluster, and
// the cluster that looks largest from its nearest reflector (its bounding radius over its
// distance) is split at the median of its members' centres along their longest axis, until the
// target count is reached. Objects that move (keyframed or deforming) are never merged: each is
// a group of its own, so that a group's impostor, placed once, never needs to follow motion
// its members do not share (docs/methods.md, "Impostor groups").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "methods/impostor/candidate_cells.h"
#include "scene/scene.h"

namespace mirage {

// --impostor-groups auto|per-object|N.
struct GroupSetting {
  enum class Mode { kAuto, kPerObject, kCount };
  Mode mode = Mode::kAuto;
  int count = 0;  // kCount: the groups asked for (1..kMaxGroupCount)
};
inline constexpr int kMaxGroupCount = 4096;
// The groups per reflector `auto` allows at most: every reflected ray tests each of its
// reflector's groups, so the list's length is the per-pixel cost.
inline constexpr int kAutoGroupsPerReflector = 64;
// Throws InputError naming `option` and the allowed values.
GroupSetting parseGroupSetting(const std::string& text, const std::string& option);
std::string groupSettingText(const GroupSetting& setting);

struct ImpostorGroup {
  std::vector<int> members;  // instances, ascending; the first stands for the group
  Bounds3 bounds;            // the members' world bounds at time 0
};

// Splits `objects` (instances) into `target` groups (at least one), as the comment at the top
// says; fewer only when the objects are fewer, and more when more objects move than `target`
// allows (moving objects are never merged) or where a group of two or more would meet a
// reflector's bounding sphere: such a group is split first and further, up to `most` groups in
// all, until none meets one. Groups are ordered by their first member.
std::vector<ImpostorGroup> clusterObjects(const Scene& scene, const std::vector<int>& objects,
                                          int target, int most = kMaxGroupCount);
// Each object a group of its own.
std::vector<ImpostorGroup> singletonGroups(const Scene& scene, const std::vector<int>& objects);

// What an impostor method's storage costs as a function of its group count G: texture layers
// (of its largest array) fixed + G x per_group, and bytes likewise.
struct GroupCost {
  int64_t fixed_layers = 0, layers_per_group = 0;
  uint64_t fixed_bytes = 0, bytes_per_group = 0;
  int64_t layers(int groups) const { return fixed_layers + int64_t(groups) * layers_per_group; }
  uint64_t bytes(int groups) const { return fixed_bytes + uint64_t(groups) * bytes_per_group; }
};

// The caps `auto` keeps within.
struct GroupCaps {
  int64_t max_layers = 2048;        // the driver's GL_MAX_ARRAY_TEXTURE_LAYERS
  uint64_t max_bytes = 2ull << 30;  // --impostor-memory
  int max_groups = kAutoGroupsPerReflector;
};

// The most groups within every cap (0: not even one), and which cap bounds it.
int groupsThatFit(const GroupCost& cost, const GroupCaps& caps, std::string* limit = nullptr);

// A method's groups, chosen by its setting, and how they were chosen (stats, messages).
struct Grouping {
  std::vector<ImpostorGroup> groups;
  int objects = 0;
  int fit = 0;  // the most groups the caps allow
  std::string
      limit;  // the cap that bounds `fit` ("texture layers", "memory", "groups per reflector")
  int64_t layers = 0;
  uint64_t bytes = 0;

  // Each group's members, as BillboardSetOptions::groups and placeDepthMaps take them.
  std::vector<std::vector<int>> memberLists() const;
};

// Groups `objects` for `method` by `setting`: per-object keeps one group an object, N asks for N
// (moving objects can make more), auto the most that fit the caps, per object when all do.
// Throws GpuError when the groups chosen cannot fit: the message says what would (a group count,
// a memory cap, or the parameter `shrink_hint` names).
Grouping chooseGroups(const Scene& scene, const std::vector<int>& objects,
                      const GroupSetting& setting, const GroupCost& cost, const GroupCaps& caps,
                      const std::string& method, const std::string& shrink_hint);

// The driver's GL_MAX_ARRAY_TEXTURE_LAYERS (needs a current context).
int64_t driverArrayLayers();

}  // namespace mirage
