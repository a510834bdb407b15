// The hybrid method's CPU structures: the point sets, the eight-way kd-tree's invariants, the
// conservative view-volume culling of its boxes (against brute-force point sampling of random
// boxes and C3RCs, and the cases the paper's two conditions miss), and the per-frame C3RC phase
// on degenerate reflector triangles.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

#include "methods/hybrid/c3rc_cull.h"
#include "methods/hybrid/c3rc_frame.h"
#include "methods/hybrid/kd_tree.h"
#include "methods/hybrid/point_set.h"
#include "scene/builtin_scenes.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

namespace sh = shading;

std::vector<vec3> clusteredPoints(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> g(0.0f, 1.0f);
  std::uniform_int_distribution<int> cluster(0, 4);
  const vec3 centres[5] = {{0, 0, 0}, {3, 1, 0}, {-2, 2, 1}, {0, -3, 2}, {1, 1, -4}};
  std::vector<vec3> p(n);
  for (vec3& q : p) q = centres[cluster(rng)] + 0.6f * vec3(g(rng), g(rng), g(rng));
  return p;
}

TEST(HybridKdTree, LeavesPartitionThePointsInsideTheirBounds) {
  const std::vector<vec3> points = clusteredPoints(50000, 1);
  KdTreeOptions options;
  options.leaf_points = 40;
  std::vector<uint32_t> order;
  const KdTree tree(points, options, order);
  ASSERT_EQ(order.size(), points.size());
  std::vector<int> seen(points.size(), 0);
  for (uint32_t o : order) ++seen[o];
  for (int s : seen) ASSERT_EQ(s, 1) << "the order is a permutation";

  std::vector<int> covered(points.size(), 0);
  for (const KdNode& node : tree.nodes()) {
    ASSERT_LT(node.begin, node.end) << "no empty node";
    for (uint32_t i = node.begin; i < node.end; ++i)
      ASSERT_TRUE(node.bounds.contains(points[order[i]]));
    if (node.leaf()) {
      EXPECT_LE(node.end - node.begin, 40u);
      for (uint32_t i = node.begin; i < node.end; ++i) ++covered[i];
      continue;
    }
    ASSERT_LE(node.child_count, 8);
    // The children split the parent's range in order, without gaps.
    uint32_t next = node.begin;
    for (uint32_t k = 0; k < node.child_count; ++k) {
      const KdNode& child = tree.nodes()[node.first_child + k];
      EXPECT_EQ(child.begin, next);
      EXPECT_EQ(child.depth, node.depth + 1);
      next = child.end;
    }
    EXPECT_EQ(next, node.end);
  }
  for (int c : covered) ASSERT_EQ(c, 1) << "every point in exactly one leaf";
  // Eight-way median splits: 50,000 points at <= 40 per leaf need 4 levels (8^3 * 40 < 50,000
  // <= 8^4 * 40), and the medians keep every leaf at 50,000 / 8^4 = 12.2 points.
  EXPECT_NEAR(tree.stats().average_leaf_depth, 4.0, 0.01);
  EXPECT_NEAR(tree.stats().points_per_leaf, 50000.0 / 4096.0, 0.01);
}

TEST(HybridKdTree, CoincidentPointsAndMinimumSizeEndTheRecursion) {
  std::vector<vec3> same(10000, vec3(1.0f, 2.0f, 3.0f));
  std::vector<uint32_t> order;
  const KdTree flat(same, {}, order);
  EXPECT_EQ(flat.stats().leaves, 1u) << "zero extent stops at the root";

  const std::vector<vec3> points = clusteredPoints(20000, 2);
  KdTreeOptions options;
  options.leaf_points = 1;
  options.min_size = 0.5f;
  const KdTree coarse(points, options, order);
  for (const KdNode& node : coarse.nodes())
    if (!node.leaf()) {
      const vec3 e = node.bounds.extent();
      EXPECT_GT(std::max({e.x, e.y, e.z}), 0.5f);
    }
  const KdTree empty(std::vector<vec3>{}, options, order);
  EXPECT_TRUE(empty.empty());
}

TEST(HybridPointSet, VerticesOrAnExactCountOnTheSurfaces) {
  const Scene scene = makeBuiltinScene("teapot-sphere");
  const std::vector<int> objects = pointSampledInstances(scene);
  for (int i : objects) {
    EXPECT_FALSE(scene.isReflector(i));
    EXPECT_FALSE(isPlanarInstance(scene, i, mat4(1.0f))) << scene.instances[size_t(i)].name;
  }
  ASSERT_FALSE(objects.empty());
  const std::vector<PointSet> vertices = samplePoints(scene, objects, {});
  size_t expected = 0;
  // Every vertex with a normal (a lathe's unused axis vertices have none).
  for (int i : objects)
    for (const vec3& n : scene.meshes[size_t(scene.instances[size_t(i)].mesh)].normals)
      expected += std::abs(glm::length(n) - 1.0f) < 1e-3f ? 1 : 0;
  size_t total = 0;
  for (const PointSet& s : vertices) {
    total += s.size();
    EXPECT_EQ(s.vertex_points, s.size());
  }
  EXPECT_EQ(total, expected);

  PointSetOptions options;
  options.total = 123457;
  const std::vector<PointSet> sampled = samplePoints(scene, objects, options);
  total = 0;
  for (const PointSet& s : sampled) {
    total += s.size();
    for (size_t k = 0; k < s.size(); k += 97) {
      ASSERT_NEAR(glm::length(s.normals[k]), 1.0f, 1e-4f)
          << scene.instances[size_t(s.instance)].name << " point " << k << " of " << s.size()
          << " (" << s.vertex_points << " vertices)";
      const Bounds3 b = scene.meshes[size_t(scene.instances[size_t(s.instance)].mesh)].bounds();
      EXPECT_TRUE(Bounds3({b.lo - vec3(1e-4f), b.hi + vec3(1e-4f)}).contains(s.positions[k]));
      EXPECT_GE(std::min({s.albedo[k].x, s.albedo[k].y, s.albedo[k].z}), 0.0f);
    }
  }
  EXPECT_EQ(total, 123457u) << "--points is exact";
  // Deterministic for a seed.
  const std::vector<PointSet> again = samplePoints(scene, objects, options);
  EXPECT_EQ(again[0].positions[777], sampled[0].positions[777]);
}

// A random C3RC of the three kinds the culling sees: divergent (a convex reflector),
// convergent-then-divergent (a concave one), and arbitrary.
C3rcData randomC3rc(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  vec3 v[3];
  for (vec3& p : v) p = vec3(u(rng), u(rng), 0.3f * u(rng));
  vec3 d[3];
  const vec3 centroid = (v[0] + v[1] + v[2]) / 3.0f;
  const vec3 focus = centroid + vec3(0.3f * u(rng), 0.3f * u(rng), 1.5f + u(rng));
  for (int k = 0; k < 3; ++k) {
    if (kind == 0)
      d[k] = glm::normalize(vec3(0, 0, 1) + 0.8f * (v[k] - centroid) +
                            0.1f * vec3(u(rng), u(rng), u(rng)));
    else if (kind == 1)
      d[k] = glm::normalize(focus - v[k]);
    else
      d[k] = glm::normalize(vec3(u(rng), u(rng), 0.2f + std::abs(u(rng))));
  }
  return makeC3rc(v[0], v[1], v[2], d[0], d[1], d[2], 100.0f);
}

bool anyPointProjects(const C3rcData& c, const Bounds3& box, int n) {
  vec4 p0, p1, p2;
  for (int x = 0; x <= n; ++x)
    for (int y = 0; y <= n; ++y)
      for (int z = 0; z <= n; ++z) {
        const vec3 t = vec3(float(x), float(y), float(z)) / float(n);
        if (sh::c3rc_project(c, glm::mix(box.lo, box.hi, t), 0.0f, true, p0, p1, p2) > 0)
          return true;
      }
  return false;
}

TEST(HybridCulling, NeverCullsABoxHoldingAProjectingPoint) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f), s(0.02f, 1.5f);
  int holding = 0, culled = 0, boxes = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const C3rcData c = randomC3rc(rng, trial % 3);
    for (int b = 0; b < 12; ++b, ++boxes) {
      const vec3 lo(u(rng), u(rng), u(rng) + 1.0f);
      const Bounds3 box{lo, lo + vec3(s(rng), s(rng), s(rng))};
      const bool meets = boxMeetsViewVolume(c, box);
      const bool rejected = hullRejects(c, box);
      if (anyPointProjects(c, box, 6)) {
        ++holding;
        ASSERT_TRUE(meets) << "trial " << trial << " box " << b;
        ASSERT_FALSE(rejected) << "trial " << trial << " box " << b;
      }
      culled += (!meets || rejected) ? 1 : 0;
    }
  }
  std::printf("%d boxes: %d hold a projecting point, %d culled\n", boxes, holding, culled);
  EXPECT_GT(holding, 500);
  EXPECT_GT(culled, boxes / 4) << "the culling must cull";
}

TEST(HybridCulling, CasesThePapersTwoConditionsMiss) {
  // A thin pencil of rays through a big box: no corner of the box projects and no face edge
  // crosses a side wall (the walls meet the faces in small closed curves), yet the box holds
  // projecting points. The construction rays find it.
  const C3rcData pencil =
      makeC3rc({0, 0, 0}, {0.01f, 0, 0}, {0, 0.01f, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 100.0f);
  const Bounds3 big{{-1, -1, 2}, {1, 1, 4}};
  ASSERT_TRUE(anyPointProjects(pencil, big, 200));
  EXPECT_TRUE(boxMeetsViewVolume(pencil, big));
  // A box straddling the base triangle.
  const C3rcData fan =
      makeC3rc({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::normalize(vec3(-0.3f, -0.3f, 1)),
               glm::normalize(vec3(0.3f, 0, 1)), glm::normalize(vec3(0, 0.3f, 1)), 100.0f);
  EXPECT_TRUE(boxMeetsViewVolume(fan, {{0.2f, 0.2f, -0.1f}, {0.3f, 0.3f, 0.1f}}));
  // Behind the base (λ < 0 only): culled by both stages.
  const Bounds3 behind{{0.2f, 0.2f, -2.0f}, {0.4f, 0.4f, -1.0f}};
  EXPECT_FALSE(boxMeetsViewVolume(fan, behind));
  EXPECT_TRUE(hullRejects(fan, behind));
  // Walls parallel to box faces (an orthographic C3RC along z over an axis-aligned triangle):
  // a box beside it is culled, a box it passes through is kept.
  const C3rcData ortho =
      makeC3rc({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 100.0f);
  EXPECT_FALSE(boxMeetsViewVolume(ortho, {{1.2f, 0.1f, 1.0f}, {1.5f, 0.5f, 2.0f}}));
  EXPECT_TRUE(boxMeetsViewVolume(ortho, {{0.9f, -0.5f, 1.0f}, {1.5f, 0.5f, 2.0f}}));
  EXPECT_TRUE(boxMeetsViewVolume(ortho, {{0.0f, 0.0f, 1.0f}, {1.0f, 1.0f, 2.0f}}))
      << "faces flush with the walls";
  // A box across the far cap T(λmax), where the root search ends, inside the walls: its low
  // corner lies beyond the cap and projects nowhere; the cap's triangle test keeps it.
  const C3rcData shallow =
      makeC3rc({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}, 1.5f);
  const Bounds3 across_cap{{0.2f, 0.2f, -1.6f}, {0.3f, 0.3f, -1.4f}};
  ASSERT_TRUE(anyPointProjects(shallow, across_cap, 6));
  EXPECT_FALSE(hullRejects(shallow, across_cap));
  EXPECT_TRUE(boxMeetsViewVolume(shallow, across_cap));
  EXPECT_FALSE(boxMeetsViewVolume(shallow, {{0.2f, 0.2f, -1.8f}, {0.3f, 0.3f, -1.6f}}))
      << "wholly beyond the cap";
}

TEST(HybridC3rcFrame, DegenerateReflectorTrianglesAreSkippedAndCounted) {
  Scene scene;
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {0, 0, 1}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  // A good triangle, a zero-area one (collinear), and one with a NaN normal.
  mesh.triangles = {{0, 1, 2}, {0, 3, 4}, {0, 1, 5}};
  mesh.normals[5] = vec3(std::nanf(""), 0, 0);
  scene.meshes.push_back(mesh);
  scene.materials.push_back(Material::mirror("m"));
  scene.instances.push_back({"mirror", 0, 0, {}, {}, {}, {}});
  const std::vector<PointSet> none;
  const PointStore store(scene, {}, {});
  const std::vector<std::vector<uint32_t>> pixels = {{10, 10, 10}};
  const C3rcFrame frame =
      buildC3rcFrame(scene, {0}, pixels, {mat4(1.0f)}, vec3(0.3f, 0.3f, 3.0f), store, {});
  EXPECT_EQ(frame.visible_triangles, 3);
  EXPECT_EQ(frame.degenerate_triangles, 2);
  EXPECT_TRUE(frame.items.empty()) << "no points: nothing to splat";
  EXPECT_EQ(store.pointCount(), 0u);
}

// The splatting pass's runs cover every item's taken points (the strides applied) once, in
// order, and each stays within the loop budget and the item cap; greedy: a run ends only where
// the next point step or item would not fit.
TEST(HybridC3rcFrame, ItemRunsCoverEveryPointOnceWithinTheLoopBudget) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> count(1, 4096);
  std::uniform_real_distribution<float> stride(1.0f, 40.0f);
  std::vector<ivec4> items;
  for (int i = 0; i < 3000; ++i)
    items.emplace_back(i / 7, 0, count(rng), std::bit_cast<int>(i % 5 == 0 ? 1.0f : stride(rng)));
  auto taken = [](const ivec4& it) {
    const float s = std::bit_cast<float>(it.w);
    return s > 1.0f ? (long long)std::ceil(float(it.z) / s) : (long long)it.z;
  };
  for (const long long point_cost : {20LL, 300LL, 3200LL}) {
    const RunLimits limits{point_cost, 61440, 64, 8};
    const std::vector<SplatRun> runs = itemRuns(items, limits);
    ASSERT_FALSE(runs.empty());
    // Every item's points [0, taken) exactly once, in order.
    size_t item = 0;
    long long next = 0;
    for (size_t r = 0; r < runs.size(); ++r) {
      const SplatRun& run = runs[r];
      ASSERT_EQ(size_t(run.x), item) << "run " << r;
      ASSERT_EQ(run.y, next) << "run " << r;
      ASSERT_LE(run.x, run.z);
      EXPECT_LE(size_t(run.z - run.x + 1), limits.max_items);
      const long long cost = runLoopCost(items, run, point_cost, 8);
      EXPECT_LE(cost, limits.budget) << "run " << r << " at point cost " << point_cost;
      ASSERT_LE(run.w, taken(items[size_t(run.z)]));
      ASSERT_GT(run.z > run.x ? 1 : run.w - run.y, 0) << "run " << r << " is empty";
      item = size_t(run.z);
      next = run.w;
      if (next == taken(items[item])) {
        ++item;
        next = 0;
      }
      // Greedy: one more step of the next item's points would not have fitted (or the cap).
      if (r + 1 < runs.size() && size_t(run.z - run.x + 1) < limits.max_items &&
          next == 0) {
        SplatRun grown = run;
        grown.z = int(item);
        grown.w = int(std::min<long long>(8, taken(items[item])));
        EXPECT_GT(runLoopCost(items, grown, point_cost, 8), limits.budget) << "run " << r;
      }
    }
    EXPECT_EQ(item, items.size()) << "every point covered";
  }
  const RunLimits cheap{20, 61440, 64, 8};
  EXPECT_LT(itemRuns(items, cheap).size(), items.size() / 4) << "strided items share runs";
  EXPECT_TRUE(itemRuns({}, cheap).empty());
  EXPECT_EQ(itemRuns(items, RunLimits{20, 61440, 1, 8}).size(), items.size()) << "one item a run";
}

}  // namespace
}  // namespace mirage::test
