// The culling of kd-nodes whose points all face away from a reflector triangle (normal_cone.h):
// every node's cone holds its points' normals; a box the cone test drops holds no point, with a
// normal in the cone, that faces any of the three vertices (brute force over random boxes, cones
// and triangles, normals on the cone's rim included); and on a scene's closed object the leaves
// it drops hold only points the splatting skips, and they are many.
#include <gtest/gtest.h>

#include <random>

#include "methods/hybrid/c3rc_cull.h"
#include "methods/hybrid/c3rc_cull_shared.h"
#include "methods/hybrid/c3rc_frame.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/normal_cone.h"
#include "methods/hybrid/point_store.h"
#include "scene/builtin_scenes.h"

namespace mirage::test {
namespace {

namespace sh = shading;

// Points on two spheres (closed surfaces, every normal direction) with their outward normals.
PointSet spherePoints(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> g(0.0f, 1.0f);
  PointSet set;
  for (size_t i = 0; i < n; ++i) {
    const vec3 normal = glm::normalize(vec3(g(rng), g(rng), g(rng)));
    set.positions.push_back((i % 2 ? vec3(3, 0, 0) : vec3(0)) + normal);
    set.normals.push_back(normal);
  }
  return set;
}

TEST(HybridNormalCones, HoldEveryNormalOfTheirNode) {
  PointSet set = spherePoints(20000, 3);
  std::vector<uint32_t> order;
  const KdTree tree(set.positions, {64, 0.0f}, order);
  std::vector<vec3> normals(set.normals.size());
  for (size_t i = 0; i < order.size(); ++i) normals[i] = set.normals[order[i]];
  const std::vector<vec4> cones = normalCones(tree, normals);
  ASSERT_EQ(cones.size(), tree.nodes().size());
  int narrow = 0;
  for (size_t i = 0; i < cones.size(); ++i) {
    const KdNode& node = tree.nodes()[i];
    if (cones[i].w < -1.0f) continue;  // no cone: culls nothing
    EXPECT_NEAR(glm::length(vec3(cones[i])), 1.0f, 1e-5f);
    for (uint32_t p = node.begin; p < node.end; ++p)
      ASSERT_GE(glm::dot(vec3(cones[i]), normals[p]), cones[i].w) << "node " << i;
    narrow += node.leaf() && cones[i].w > 0.7f ? 1 : 0;
  }
  EXPECT_GT(narrow, int(tree.stats().leaves) / 2) << "leaves on a sphere have narrow cones";
  EXPECT_LT(cones[0].w, -0.99f) << "the root holds every direction: the whole sphere";
  EXPECT_TRUE(normalCones(tree, {})[5].w < -1.0f) << "an open surface: no cones";
}

// A unit normal at angle `angle` from `axis`, turned by `turn` about it.
vec3 normalInCone(const vec3& axis, float angle, float turn) {
  const vec3 helper = std::abs(axis.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0);
  const vec3 t = glm::normalize(glm::cross(axis, helper)), b = glm::cross(axis, t);
  return std::cos(angle) * axis + std::sin(angle) * (std::cos(turn) * t + std::sin(turn) * b);
}

TEST(HybridConeCulling, NeverDropsABoxWithAPointFacingAVertex) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), unit(0.0f, 1.0f);
  int dropped = 0, trials = 4000;
  for (int trial = 0; trial < trials; ++trial) {
    const vec3 lo(u(rng), u(rng), u(rng));
    const vec3 hi = lo + vec3(0.05f) + 0.5f * vec3(unit(rng), unit(rng), unit(rng));
    const vec3 axis = glm::normalize(vec3(u(rng), u(rng), u(rng)));
    const float half_angle = 1.4f * unit(rng);
    const vec4 cone(axis, std::cos(half_angle));
    // Vertices mostly behind the cone's points, some beside: both answers occur.
    vec3 v[3];
    const vec3 behind = 0.5f * (lo + hi) - (1.0f + 3.0f * unit(rng)) * axis;
    for (vec3& p : v) p = behind + 1.5f * vec3(u(rng), u(rng), u(rng));
    if (!sh::c3rc_cone_faces_away(cone, lo, hi, v[0], v[1], v[2])) continue;
    ++dropped;
    // Every point of a grid over the box, each with normals on the rim and inside the cone.
    for (int x = 0; x <= 4; ++x)
      for (int y = 0; y <= 4; ++y)
        for (int z = 0; z <= 4; ++z) {
          const vec3 q = glm::mix(lo, hi, vec3(float(x), float(y), float(z)) / 4.0f);
          for (float f : {0.0f, 0.5f, 1.0f})
            for (int k = 0; k < 8; ++k) {
              const vec3 n = normalInCone(axis, f * half_angle, 0.785f * float(k));
              ASSERT_TRUE(sh::hybrid_faces_away(n, q, v[0], v[1], v[2]))
                  << "trial " << trial << ": a point faces a vertex";
            }
        }
  }
  std::printf("%d of %d boxes dropped\n", dropped, trials);
  EXPECT_GT(dropped, trials / 10) << "the test must drop boxes";
  // No cone (w < −1) never drops.
  EXPECT_FALSE(sh::c3rc_cone_faces_away(vec4(0, 0, 1, kNoNormalCone), vec3(0), vec3(1),
                                        vec3(0, 0, -5), vec3(1, 0, -5), vec3(0, 1, -5)));
  // A flat patch facing +z, a triangle far below it: dropped; the same triangle above: kept.
  const vec4 up(0, 0, 1, 0.99f);
  EXPECT_TRUE(sh::c3rc_cone_faces_away(up, vec3(0), vec3(1, 1, 0.01f), vec3(0, 0, -5),
                                       vec3(1, 0, -5), vec3(0, 1, -5)));
  EXPECT_FALSE(sh::c3rc_cone_faces_away(up, vec3(0), vec3(1, 1, 0.01f), vec3(0, 0, 5),
                                        vec3(1, 0, 5), vec3(0, 1, 5)));
}

// The dropped leaves of the scene's closed objects, brute force: every point faces away from the
// C3RC's triangle (in object space, where the culling runs), as the splatting's test would say.
TEST(HybridConeCulling, DropsOnlyLeavesWhosePointsAllFaceAway) {
  const Scene scene = makeBuiltinScene("teapot-sphere");
  PointSetOptions points;
  points.total = 60000;
  const PointStore store(scene, points, KdTreeOptions{});
  std::vector<int> reflectors = scene.reflectorInstances();
  std::vector<std::vector<uint32_t>> pixels;
  for (int r : reflectors)
    pixels.emplace_back(scene.meshes[size_t(scene.instances[size_t(r)].mesh)].triangleCount(), 1u);
  std::vector<mat4> matrices;
  for (const Instance& inst : scene.instances) matrices.push_back(inst.matrixAt(0.0f));
  C3rcFrameOptions options;
  options.cull_on_cpu = false;
  options.reach = 2.0f * scene.bounds(0.0f).radius();
  const C3rcFrame frame =
      buildC3rcFrame(scene, reflectors, pixels, matrices, scene.camera().position, store, options);
  long long closed_leaves = 0, dropped = 0, dropped_points = 0;
  std::vector<uint32_t> all, kept;
  for (const PointCloud& cloud : store.clouds()) {
    if (!cloud.points.closed) continue;
    const mat4 to_object = glm::inverse(matrices[size_t(cloud.points.instance)]);
    for (size_t i = 0; i < frame.c3rcs.size(); i += 3) {
      const C3rcData c = transformC3rc(frame.c3rcs[i], to_object);
      CullCounters counters;
      all.clear();
      kept.clear();
      cullLeaves(cloud.tree, c, Culling::kInner, {}, all, counters);
      cullLeaves(cloud.tree, c, Culling::kInner, cloud.cones, kept, counters);
      closed_leaves += (long long)all.size();
      for (uint32_t leaf : all) {
        if (std::find(kept.begin(), kept.end(), leaf) != kept.end()) continue;
        ++dropped;
        const KdNode& node = cloud.tree.nodes()[leaf];
        dropped_points += node.end - node.begin;
        for (uint32_t p = node.begin; p < node.end; ++p)
          ASSERT_TRUE(sh::hybrid_faces_away(cloud.points.normals[p], cloud.points.positions[p],
                                            vec3(c.v0), vec3(c.v1), vec3(c.v2)))
              << "C3RC " << i << " leaf " << leaf << " point " << p;
      }
      EXPECT_LE(kept.size(), all.size());
    }
  }
  std::printf("%lld of %lld kept leaves dropped (%lld points)\n", dropped, closed_leaves,
              dropped_points);
  ASSERT_GT(closed_leaves, 0) << "the scene has a closed point-sampled object";
  EXPECT_GT(dropped, closed_leaves / 10) << "a closed object's far side is dropped";
}

}  // namespace
}  // namespace mirage::test
