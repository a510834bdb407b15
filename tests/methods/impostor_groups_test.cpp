// Impostor groups (methods/impostor/impostor_groups.h): the setting's text, the clustering (a
// partition of the objects into the count asked for, moving objects never merged), the caps'
// arithmetic, and on the GPU: auto changes nothing where every object fits, and renders with
// depth maps a scene whose per-object maps the driver cannot hold, close to the ray tracer.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "core/error.h"
#include "methods/depthmap/depthmap_set.h"
#include "methods/frame.h"
#include "methods/impostor/impostor_groups.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

TEST(ImpostorGroups, SettingIsAutoPerObjectOrACount) {
  EXPECT_EQ(parseGroupSetting("auto", "--g").mode, GroupSetting::Mode::kAuto);
  EXPECT_EQ(parseGroupSetting("per-object", "--g").mode, GroupSetting::Mode::kPerObject);
  const GroupSetting n = parseGroupSetting("12", "--g");
  EXPECT_EQ(n.mode, GroupSetting::Mode::kCount);
  EXPECT_EQ(n.count, 12);
  EXPECT_EQ(groupSettingText(n), "12");
  for (const char* bad : {"", "0", "-3", "4097", "12x", "all", " 3"}) {
    try {
      parseGroupSetting(bad, "--impostor-groups");
      ADD_FAILURE() << "'" << bad << "' was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--impostor-groups"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("auto, per-object, or a group count 1..4096"),
                std::string::npos)
          << e.what();
    }
  }
}

// Every object in exactly one group, groups ordered by their first member, members ascending.
void expectPartition(const std::vector<ImpostorGroup>& groups, std::vector<int> objects) {
  std::vector<int> seen;
  for (size_t g = 0; g < groups.size(); ++g) {
    ASSERT_FALSE(groups[g].members.empty());
    EXPECT_TRUE(std::is_sorted(groups[g].members.begin(), groups[g].members.end()));
    if (g > 0) {
      EXPECT_LT(groups[g - 1].members.front(), groups[g].members.front());
    }
    seen.insert(seen.end(), groups[g].members.begin(), groups[g].members.end());
  }
  std::sort(seen.begin(), seen.end());
  std::sort(objects.begin(), objects.end());
  EXPECT_EQ(seen, objects);
}

// No group of two or more meets a reflector's bounding sphere.
void expectNoGroupMeetsAReflector(const Scene& scene, const std::vector<ImpostorGroup>& groups) {
  for (const ImpostorGroup& g : groups) {
    if (g.members.size() < 2) continue;
    for (int r : scene.reflectorInstances()) {
      const Bounds3 b = scene.instanceBounds(r);
      EXPECT_GT(glm::length(g.bounds.center() - b.center()), g.bounds.radius() + b.radius())
          << "a group of " << g.members.size() << " meets reflector "
          << scene.instances[size_t(r)].name;
    }
  }
}

// The count asked, or more where a group would meet a reflector (NoGroupStraddlesAReflector):
// plaza's mirrors stand among its objects.
TEST(ImpostorGroups, ClusteringPartitionsTheObjectsIntoTheCountAsked) {
  const Scene plaza = makeBuiltinScene("plaza");
  const std::vector<int> objects = depthMappedObjects(plaza);
  ASSERT_EQ(objects.size(), 240u);
  for (int target : {1, 2, 29, 100, 240, 500}) {
    const std::vector<ImpostorGroup> groups = clusterObjects(plaza, objects, target);
    EXPECT_GE(int(groups.size()), std::min(target, 240)) << target;
    EXPECT_LE(int(groups.size()), 240) << target;
    expectPartition(groups, objects);
    expectNoGroupMeetsAReflector(plaza, groups);
    // A group's bounds hold its members'.
    for (const ImpostorGroup& g : groups)
      for (int m : g.members) {
        const Bounds3 b = plaza.instanceBounds(m);
        EXPECT_TRUE(g.bounds.contains(b.lo) && g.bounds.contains(b.hi));
      }
  }
}

TEST(ImpostorGroups, TheSplitIsSpatialSoGroupsAreCompact) {
  // 240 objects on a 16 x 15 grid of 1.8 m cells in 16 groups: each group spans a few cells,
  // far less than the square (29 x 27 m).
  const Scene plaza = makeBuiltinScene("plaza");
  const std::vector<ImpostorGroup> groups = clusterObjects(plaza, depthMappedObjects(plaza), 16);
  const float square = plaza.bounds().radius();
  for (const ImpostorGroup& g : groups) EXPECT_LT(g.bounds.radius(), 0.35f * square);
}

TEST(ImpostorGroups, MovingObjectsAreNeverMerged) {
  Scene s = mirrorAmongObjects(8);
  std::vector<int> objects;
  for (int i : s.diffuseInstances()) objects.push_back(i);
  // Objects 1 and 2 move (keyframed).
  for (int k : {1, 2}) {
    Instance& inst = s.instances[size_t(objects[size_t(k)])];
    Keyframe a{0.0f, inst.transform}, b{1.0f, inst.transform};
    b.transform.translation += vec3(0.0f, 0.5f, 0.0f);
    inst.animation.keys = {a, b};
  }
  for (int target : {1, 3, 5}) {
    // At most `target` groups but for the moving objects (none split for meeting the mirror).
    const std::vector<ImpostorGroup> groups = clusterObjects(s, objects, target, target);
    expectPartition(groups, objects);
    EXPECT_EQ(int(groups.size()), std::max(target, 3)) << target;
    for (const ImpostorGroup& g : groups)
      if (g.members.size() > 1) {
        for (int m : g.members) EXPECT_TRUE(s.instances[size_t(m)].animation.empty());
      }
  }
}

TEST(ImpostorGroups, TheCapsBoundTheCount) {
  GroupCost cost;
  cost.fixed_layers = 100;
  cost.layers_per_group = 20;
  cost.fixed_bytes = 10 << 20;
  cost.bytes_per_group = 4 << 20;
  GroupCaps caps;
  caps.max_layers = 2048;
  caps.max_bytes = 1ull << 30;
  caps.max_groups = 1000;
  std::string limit;
  EXPECT_EQ(groupsThatFit(cost, caps, &limit), (2048 - 100) / 20);  // 97 by layers
  EXPECT_EQ(limit, "texture layers");
  caps.max_bytes = 210 << 20;
  EXPECT_EQ(groupsThatFit(cost, caps, &limit), (210 - 10) / 4);  // 50 by memory
  EXPECT_EQ(limit, "memory");
  caps.max_groups = 30;
  EXPECT_EQ(groupsThatFit(cost, caps, &limit), 30);
  EXPECT_EQ(limit, "groups per reflector");
  caps.max_bytes = 12 << 20;  // the fixed part and no group
  EXPECT_EQ(groupsThatFit(cost, caps, &limit), 0);
  EXPECT_EQ(limit, "memory");
}

// The depth-map cost at the defaults: 60 SRDM layers a map, nothing fixed.
GroupCost srdmCost() {
  GroupCost cost;
  cost.layers_per_group = 60;
  cost.bytes_per_group = 1 << 20;
  return cost;
}

TEST(ImpostorGroups, AutoIsPerObjectWhileEveryObjectFits) {
  const Scene s = mirrorAmongObjects(20);
  const std::vector<int> objects = depthMappedObjects(s);
  const Grouping g = chooseGroups(s, objects, {}, srdmCost(), GroupCaps{}, "test", "");
  EXPECT_EQ(g.groups.size(), objects.size());
  EXPECT_EQ(g.layers, 60 * 20);
}

TEST(ImpostorGroups, AutoMergesWhatTheDriverCannotHoldAndPerObjectSaysWhatWould) {
  const Scene s = mirrorAmongObjects(48);
  const std::vector<int> objects = depthMappedObjects(s);
  const Grouping g = chooseGroups(s, objects, {}, srdmCost(), GroupCaps{}, "test", "");
  EXPECT_EQ(g.groups.size(), 2048u / 60u);  // 34
  EXPECT_EQ(g.limit, "texture layers");
  expectPartition(g.groups, objects);
  try {
    chooseGroups(s, objects, {GroupSetting::Mode::kPerObject, 0}, srdmCost(), GroupCaps{},
                 "depth maps", "");
    ADD_FAILURE() << "per-object was accepted";
  } catch (const GpuError& e) {
    EXPECT_NE(std::string(e.what()).find("2880 texture layers"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--impostor-groups auto (34 groups) would fit"),
              std::string::npos)
        << e.what();
  }
  // auto with more moving objects than fit: refused, saying why.
  Scene moving = mirrorAmongObjects(48);
  for (int i : depthMappedObjects(moving)) {
    Instance& inst = moving.instances[size_t(i)];
    inst.animation.keys = {Keyframe{0.0f, inst.transform}, Keyframe{1.0f, inst.transform}};
  }
  try {
    chooseGroups(moving, objects, {}, srdmCost(), GroupCaps{}, "depth maps", "");
    ADD_FAILURE() << "48 moving objects were accepted";
  } catch (const GpuError& e) {
    EXPECT_NE(std::string(e.what()).find("moving objects are never merged"), std::string::npos)
        << e.what();
  }
  // Not even one group: the message names what would fit.
  GroupCost huge = srdmCost();
  huge.fixed_layers = 2000;
  try {
    chooseGroups(s, objects, {}, huge, GroupCaps{}, "depth maps", "a smaller --srdm-n");
    ADD_FAILURE() << "a fixed part beyond the layers was accepted";
  } catch (const GpuError& e) {
    EXPECT_NE(std::string(e.what()).find("a smaller --srdm-n would fit"), std::string::npos)
        << e.what();
  }
}

class ImpostorGroupImages : public GlTest {};

// spheres9 at 240x160, order 2, with a renderer: a method's frame by its parameters.
struct Spheres9Frames {
  Scene scene = makeBuiltinScene("spheres9");
  ivec2 size{240, 160};
  FrameSettings settings;  // order 2
  FrameRenderer renderer{scene, size};

  std::unique_ptr<Method> render(const char* method,
                                 const std::map<std::string, std::string>& params) {
    auto m = renderer.createMethod(method, params, settings);
    renderer.render(*m, View(scene.camera(), size), 0.0f, settings);
    return m;
  }
};

TEST_F(ImpostorGroupImages, AutoIsThePerObjectFrameWhereEveryObjectFits) {
  Spheres9Frames frames;
  for (const char* method : {"billboard", "depthmap"}) {
    frames.render(method, {});
    const RenderedFrame a = frames.renderer.read();
    frames.render(method, {{"impostor-groups", "per-object"}});
    const RenderedFrame b = frames.renderer.read();
    EXPECT_TRUE(a.color.pixels() == b.color.pixels()) << method;
  }
}

TEST_F(ImpostorGroupImages, DepthMapsRenderWhatPerObjectCannotHold) {
  // 48 objects x 60 SRDM layers = 2880 layers, beyond the 2048 that llvmpipe and NVIDIA's
  // drivers hold: per-object falls back to envmap, auto renders 34 groups.
  expectFallback();
  const Scene scene = mirrorAmongObjects(48);
  const ivec2 size{240, 160};
  FrameSettings settings;
  settings.order = 1;
  {
    FrameRenderer renderer(scene, size);
    auto per_object =
        renderer.createMethod("depthmap", {{"impostor-groups", "per-object"}}, settings);
    EXPECT_NE(per_object->fallbackReason().find("--impostor-groups auto"), std::string::npos)
        << per_object->fallbackReason();
  }
  // One list a reflector (--impostor-cells 0), so that the count below is every group's.
  const RenderPair automatic = renderWithTruth(scene, "depthmap", size, settings,
                                               {{"impostor-cells", "0"}}, 0.0f, kMatchedSsaa);
  EXPECT_EQ(automatic.stats.at("depthmap_groups"), 34.0);
  EXPECT_EQ(automatic.stats.at("depthmap_objects"), 48.0);
  // A ray tests each group's maps once (no billboard but for them: no floor, one reflector).
  EXPECT_EQ(automatic.stats.at("impostor_candidates_per_ray"), 34.0);
  const RenderPair envmap =
      renderWithTruth(scene, "envmap", size, settings, {}, 0.0f, kMatchedSsaa);
  std::printf("reflector PSNR: depthmap in 34 groups %.2f dB, envmap %.2f dB\n",
              reflectorPsnr(automatic), reflectorPsnr(envmap));
  EXPECT_GT(reflectorPsnr(automatic), reflectorPsnr(envmap) + 3.0);
}

TEST_F(ImpostorGroupImages, BillboardGroupsTradeErrorForCountMonotonically) {
  // The same 48 objects as 16 and 24 billboard groups and one an object: a group's billboard
  // stands in a plane through its centre, so its members' parallax grows with its size, and the
  // error falls as the groups grow in number. Fewer than 16 are not made: every larger group of
  // the ring would meet the mirror (NoGroupStraddlesAReflector). Measured at 240x160, matched
  // 2x2: 30.3, 33.1 and 36.3 dB; envmap-infinite (no objects at all) 25.7 dB.
  const Scene scene = mirrorAmongObjects(48);
  const ivec2 size{240, 160};
  FrameSettings settings;
  settings.order = 1;
  std::vector<double> psnr;
  for (const char* groups : {"16", "24", "per-object"}) {
    const RenderPair p =
        renderWithTruth(scene, "billboard", size, settings,
                        {{"impostor-groups", groups}, {"impostor-cells", "0"}}, 0.0f, kMatchedSsaa);
    const double expected = groups == std::string("per-object") ? 48.0 : std::stod(groups);
    EXPECT_EQ(p.stats.at("impostor_groups"), expected);
    EXPECT_EQ(p.stats.at("diffuse_billboards"), expected);
    // One reflector, no planar object, order 1, one list: a ray tests the groups' billboards.
    EXPECT_EQ(p.stats.at("impostor_candidates_per_ray"), expected);
    EXPECT_EQ(p.stats.at("impostor_rays_per_pixel"), 1.0);
    psnr.push_back(reflectorPsnr(p));
    std::printf("reflector PSNR, billboard in %s groups: %.2f dB\n", groups, psnr.back());
  }
  for (size_t k = 1; k < psnr.size(); ++k) EXPECT_GT(psnr[k], psnr[k - 1] + 1.0);
  const double probe = reflectorPsnr(
      renderWithTruth(scene, "envmap-infinite", size, settings, {}, 0.0f, kMatchedSsaa));
  EXPECT_GT(psnr[1], probe + 3.0);
}

// A group whose bounding sphere meets a reflector's would stand one billboard through its centre,
// next to the reflector: members beside the reflector, which its rays reach leaving along the
// billboard's plane or away from it, vanish. Such a group is split further, whatever the count
// asked (as moving objects are never merged), until none meets a reflector's sphere or it is a
// single object: two groups of the ring around the mirror, each half a ring around it, become
// more, and the frame comes close to per-object billboards'.
TEST_F(ImpostorGroupImages, NoGroupStraddlesAReflector) {
  const Scene scene = mirrorAmongObjects(48);
  const ivec2 size{240, 160};
  FrameSettings settings;
  settings.order = 1;
  using Params = std::map<std::string, std::string>;
  const Params cells0 = {{"impostor-cells", "0"}};
  auto with = [&](const char* groups) {
    Params p = cells0;
    p["impostor-groups"] = groups;
    return renderWithTruth(scene, "billboard", size, settings, p, 0.0f, kMatchedSsaa);
  };
  const RenderPair two = with("2"), per_object = with("per-object");
  std::printf("reflector PSNR: 2 groups asked (%.0f made) %.2f dB, per object %.2f dB\n",
              two.stats.at("impostor_groups"), reflectorPsnr(two), reflectorPsnr(per_object));
  EXPECT_GT(two.stats.at("impostor_groups"), 2.0);
  expectNoGroupMeetsAReflector(scene, clusterObjects(scene, depthMappedObjects(scene), 2));
  EXPECT_TRUE(meetsFloor(reflectorPsnr(two), floors::kBillboardGroupsBesideAReflector));
}

// --impostor-memory is the user's setting: one that cannot be met is bad input (an InputError,
// exit 2, naming it and what would fit), never a fallback; and depthmap counts against it the
// billboard stage beside its maps (its planar objects' billboards, the capture's textures), which
// went unchecked: 2,048-texel billboards of teapot-sphere's floor take 44 MiB alone.
TEST_F(ImpostorGroupImages, AnImpostorMemoryThatCannotBeMetIsBadInput) {
  const Scene scene = makeBuiltinScene("teapot-sphere");
  FrameRenderer renderer(scene, {64, 48});
  FrameSettings settings;
  using Params = std::map<std::string, std::string>;
  const auto refused = [&](const std::string& method, const Params& params) {
    try {
      renderer.createMethod(method, params, settings);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // One group of 1,024-texel depth maps is 30 MiB.
  std::string why = refused("depthmap", {{"depthmap-size", "1024"}, {"impostor-memory", "16"}});
  EXPECT_NE(why.find("--impostor-memory 16 (MiB) cannot be met"), std::string::npos) << why;
  EXPECT_NE(why.find("allowed: 16..1048576"), std::string::npos) << why;
  // The stage's fixed textures count, for depthmap as for billboard.
  for (const char* method : {"depthmap", "billboard"}) {
    why = refused(method, {{"billboard-size", "2048"}, {"impostor-memory", "32"}});
    EXPECT_NE(why.find("cannot be met"), std::string::npos) << method << ": " << why;
  }
  // A count of groups beyond the cap says what would fit.
  why = refused("billboard", {{"billboard-size", "1024"},
                              {"impostor-groups", "per-object"},
                              {"impostor-memory", "30"}});
  EXPECT_NE(why.find("beyond --impostor-memory 30"), std::string::npos) << why;
  // Within it, both draw.
  for (const char* method : {"depthmap", "billboard"}) {
    auto m = renderer.createMethod(method, {{"billboard-size", "2048"}, {"impostor-memory", "128"}},
                                   settings);
    EXPECT_EQ(m->fallbackReason(), "") << method;
  }
}

TEST_F(ImpostorGroupImages, CountsTheImpostorsEachRayTests) {
  // spheres9 at order 2: every ray, first bounce or second, tests its reflector's list, the
  // floor's billboard, one per group of the six other objects and the eight other reflectors'
  // reflective billboards (the last bounce tests them too: --last-bounce all); depthmap tests
  // the six objects through their maps instead. Asked for fewer groups, the six stay apart: any
  // two of them meet a mirror sphere's bounds (NoGroupStraddlesAReflector). One list a reflector
  // (--impostor-cells 0): the cells' lists are BillboardImages.DirectionCell*'s.
  Spheres9Frames frames;
  for (const auto& [method, groups, expected] :
       {std::tuple{"billboard", "auto", 15.0}, std::tuple{"billboard", "2", 15.0},
        std::tuple{"depthmap", "auto", 15.0}, std::tuple{"depthmap", "3", 15.0}}) {
    const std::map<std::string, double> stats =
        frames.render(method, {{"impostor-groups", groups}, {"impostor-cells", "0"}})->stats();
    EXPECT_EQ(stats.at("impostor_candidates_per_ray"), expected) << method << " " << groups;
    EXPECT_GT(stats.at("impostor_pixels"), 1000.0);
    // Some rays bounce twice, off another sphere's reflective billboard; most leave at once.
    EXPECT_GT(stats.at("impostor_rays_per_pixel"), 1.0);
    EXPECT_LT(stats.at("impostor_rays_per_pixel"), 2.0);
  }
}

}  // namespace
}  // namespace mirage::test
