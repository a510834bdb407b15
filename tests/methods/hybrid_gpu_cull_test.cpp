// The hybrid method's GPU culling (--hybrid-cull-on gpu): the compute shader keeps exactly the
// (C3RC, leaf) pairs of the CPU culling, with the same counters, in every culling mode, grows
// its buffers instead of dropping items, keeps the same boxes for the folds of a concave
// reflector's view volumes, and the frame it gives equals the CPU path's bit for bit, under
// rigid motion too.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "methods/frame.h"
#include "methods/hybrid/c3rc.h"
#include "methods/hybrid/c3rc_frame.h"
#include "methods/hybrid/kd_gpu_cull.h"
#include "methods/hybrid/kd_gpu_shared.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class HybridGpuCull : public GlTest {};

// teapot-sphere without its floor, the teapot turned and moved: a non-identity object space.
Scene movedObjects() {
  Scene scene = teapotSphereObjectsOnly();
  for (Instance& inst : scene.instances)
    if (inst.name == "teapot") {
      Transform moved = inst.transform;
      moved.translation += vec3(0.25f, 0.0f, 0.35f);
      moved.rotation = glm::angleAxis(glm::radians(50.0f), vec3(0, 1, 0)) * moved.rotation;
      inst.animation.keys = {{0.0f, inst.transform}, {1.0f, moved}};
    }
  return scene;
}

using Pair = std::tuple<int, int, int>;  // C3RC, first point, point count

// The C3RCs of every `stride`-th reflector triangle (counted visible whichever way they face).
C3rcFrame someC3rcs(const Scene& scene, const std::vector<mat4>& matrices, const PointStore& store,
                    size_t stride = 8) {
  std::vector<int> reflectors = scene.reflectorInstances();
  std::vector<std::vector<uint32_t>> pixels;
  for (int r : reflectors) {
    pixels.emplace_back(scene.meshes[size_t(scene.instances[size_t(r)].mesh)].triangleCount(), 0u);
    for (size_t t = 0; t < pixels.back().size(); t += stride) pixels.back()[t] = 1;
  }
  C3rcFrameOptions options;
  options.cull_on_cpu = false;
  options.reach = 2.0f * scene.bounds(0.5f).radius();
  return buildC3rcFrame(scene, reflectors, pixels, matrices, scene.camera().position, store,
                        options);
}

// The CPU culling's kept leaves, unmerged, as the GPU path writes them.
std::vector<Pair> cpuPairs(const std::vector<C3rcData>& c3rcs, const std::vector<mat4>& matrices,
                           const PointStore& store, Culling culling, bool cull_backfaces,
                           CullCounters& counters) {
  std::vector<Pair> pairs;
  std::vector<uint32_t> leaves;
  for (size_t i = 0; i < c3rcs.size(); ++i) {
    if (int(c3rcs[i].info.z) & MIRAGE_C3RC_DEGENERATE) continue;
    for (const PointCloud& cloud : store.clouds()) {
      const mat4 to_object = glm::inverse(matrices[size_t(cloud.points.instance)]);
      leaves.clear();
      cullLeaves(cloud.tree, transformC3rc(c3rcs[i], to_object), culling,
                 cull_backfaces ? std::span<const vec4>(cloud.cones) : std::span<const vec4>(),
                 leaves, counters);
      for (uint32_t leaf : leaves) {
        const KdNode& node = cloud.tree.nodes()[leaf];
        pairs.emplace_back(int(i), int(cloud.offset + node.begin), int(node.end - node.begin));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

TEST_F(HybridGpuCull, KeepsExactlyTheCpuPairsInEveryMode) {
  const Scene scene = movedObjects();
  std::vector<mat4> matrices;
  for (const Instance& inst : scene.instances) matrices.push_back(inst.matrixAt(0.5f));
  PointSetOptions points;
  points.total = 30000;
  KdTreeOptions tree;
  tree.leaf_points = 32;  // deeper trees: more nodes, more stack
  const PointStore store(scene, points, tree);
  const C3rcFrame frame = someC3rcs(scene, matrices, store);
  ASSERT_GT(frame.c3rcs.size(), 100u);
  EXPECT_TRUE(frame.items.empty()) << "cull_on_cpu = false leaves the culling to the GPU";
  KdGpuCull gpu(store);
  int levels = 0;
  for (const PointCloud& cloud : store.clouds())
    levels = std::max(levels, cloud.tree.stats().max_depth + 1);
  // Exact first: none, last, keeps far more leaves and must grow the buffers. The normal cones
  // drop nodes in every mode but none.
  for (auto [culling, backfaces] : {std::pair{Culling::kExact, false},
                                    {Culling::kInner, true},
                                    {Culling::kInner, false},
                                    {Culling::kHull, true},
                                    {Culling::kNone, false}}) {
    SCOPED_TRACE(int(culling) * 2 + int(backfaces));
    // Without culling every pair keeps every leaf: a tenth of the C3RCs keeps the items within
    // the largest storage block.
    std::vector<C3rcData> c3rcs = frame.c3rcs;
    if (culling == Culling::kNone) c3rcs.resize(c3rcs.size() / 10);
    CullCounters cpu_counters;
    const std::vector<Pair> cpu =
        cpuPairs(c3rcs, matrices, store, culling, backfaces, cpu_counters);
    const KdGpuCullResult result = gpu.run(c3rcs, matrices, culling, backfaces);
    std::vector<Pair> got;
    for (const ivec4& item : gpu.downloadItems(result.items)) {
      EXPECT_EQ(item.w, MIRAGE_KD_ITEM_W) << "floatBitsToInt(1.0f): a stride of one";
      got.emplace_back(item.x, item.y, item.z);
    }
    std::sort(got.begin(), got.end());
    std::printf(
        "culling %d, back faces %d: %zu C3RCs, %zu pairs, %lld nodes tested, %lld kept for a "
        "fold, %lld dropped facing away, %d dispatches\n",
        int(culling), int(backfaces), c3rcs.size(), cpu.size(), cpu_counters.nodes_tested,
        cpu_counters.fold_keeps, cpu_counters.cone_rejects, result.dispatches);
    ASSERT_GT(cpu.size(), 0u);
    EXPECT_EQ(got.size(), cpu.size());
    EXPECT_TRUE(got == cpu) << "the GPU keeps the CPU's (C3RC, leaf) pairs";
    EXPECT_EQ(result.cull.nodes_tested, cpu_counters.nodes_tested);
    EXPECT_EQ(result.cull.hull_rejects, cpu_counters.hull_rejects);
    EXPECT_EQ(result.cull.exact_rejects, cpu_counters.exact_rejects);
    EXPECT_EQ(result.cull.fold_keeps, cpu_counters.fold_keeps);
    EXPECT_EQ(result.cull.cone_rejects, cpu_counters.cone_rejects);
    EXPECT_EQ(result.cull.leaves_kept, cpu_counters.leaves_kept);
    if (backfaces) {
      EXPECT_GT(cpu_counters.cone_rejects, 0) << "the moved teapot's far side";
    }
    // One dispatch per level, and one more whenever a buffer had to grow: none outgrows the
    // buffers that exact and hull left.
    EXPECT_GE(result.dispatches, levels);
    if (culling == Culling::kNone) {
      EXPECT_GT(result.dispatches, levels) << "a buffer grew";
    }
  }
}

// The concave dish's C3RCs fold: the GPU runs the fold test (c3rc_classify_box's last case) on
// the same C3RCs and keeps the same boxes for it.
TEST_F(HybridGpuCull, KeepsTheCpuPairsWhereTheViewVolumeFolds) {
  const Scene scene = makeBuiltinScene("concave-dish");
  std::vector<mat4> matrices;
  for (const Instance& inst : scene.instances) matrices.push_back(inst.matrixAt(0.0f));
  PointSetOptions points;
  points.total = 30000;
  const PointStore store(scene, points, KdTreeOptions{});
  const C3rcFrame frame = someC3rcs(scene, matrices, store, 1);
  ASSERT_GT(frame.multiple_c3rcs, 50);
  CullCounters cpu_counters;
  const std::vector<Pair> cpu =
      cpuPairs(frame.c3rcs, matrices, store, Culling::kExact, true, cpu_counters);
  KdGpuCull gpu(store);
  const KdGpuCullResult result = gpu.run(frame.c3rcs, matrices, Culling::kExact, true);
  std::vector<Pair> got;
  for (const ivec4& item : gpu.downloadItems(result.items))
    got.emplace_back(item.x, item.y, item.z);
  std::sort(got.begin(), got.end());
  std::printf("%zu C3RCs (%lld folding): %zu pairs, %lld nodes kept for a fold\n",
              frame.c3rcs.size(), frame.multiple_c3rcs, cpu.size(), cpu_counters.fold_keeps);
  EXPECT_GT(cpu_counters.fold_keeps, 0) << "the fold case is exercised";
  EXPECT_TRUE(got == cpu) << "the GPU keeps the CPU's (C3RC, leaf) pairs";
  EXPECT_EQ(result.cull.fold_keeps, cpu_counters.fold_keeps);
  EXPECT_EQ(result.cull.exact_rejects, cpu_counters.exact_rejects);
}

TEST_F(HybridGpuCull, FramesEqualTheCpuPathBitForBit) {
  const Scene scene = movedObjects();
  const ivec2 size{200, 140};
  FrameRenderer renderer(scene, size);
  FrameSettings settings;
  settings.order = 1;
  for (const char* culling : {"inner", "exact", "none"}) {
    SCOPED_TRACE(culling);
    Image images[2];
    std::map<std::string, double> stats[2];
    for (int gpu = 0; gpu < 2; ++gpu) {
      auto m = renderer.createMethod("hybrid",
                                     {{"points", "20000"},
                                      {"hybrid-culling", culling},
                                      {"hybrid-cull-on", gpu ? "gpu" : "cpu"},
                                      {"hybrid-lod", "0"}},
                                     settings);
      renderer.render(*m, View(scene.camera(), size), 0.7f, settings);
      images[gpu] = renderer.read().color;
      stats[gpu] = m->stats();
    }
    size_t differing = 0;
    for (size_t i = 0; i < images[0].pixelCount(); ++i)
      differing += images[0].pixels()[i] != images[1].pixels()[i] ? 1 : 0;
    EXPECT_EQ(differing, 0u);
    EXPECT_EQ(stats[0].at("cull_on_gpu"), 0.0);
    EXPECT_EQ(stats[1].at("cull_on_gpu"), 1.0);
    EXPECT_GT(stats[0].at("projections"), 1000.0);
    for (const char* key :
         {"projections", "points_projected", "cull_nodes_tested", "cull_leaves_kept",
          "cull_exact_rejects", "cull_cone_rejects", "splats_written"})
      EXPECT_EQ(stats[0].at(key), stats[1].at(key)) << key;
    EXPECT_GE(stats[1].at("splat_items"), stats[0].at("splat_items")) << "no merging on the GPU";
  }
}

}  // namespace
}  // namespace mirage::test
