// RayScene keeps one Embree scene for its life: a later build rewrites the moved instances'
// vertices and, in a scene where something moves, refits their BVHs inside a two-level one
// instead of building anew. Whatever the path a scene took to a time, it must trace what a
// RayScene built directly at that time traces.
#include <gtest/gtest.h>

#include <random>

#include "raytrace/ray_scene.h"
#include "scene/builtin_scenes.h"

namespace mirage {
namespace {

// Camera rays through random points of the image, and rays from random points of the scene's
// bounds in random directions (these start inside objects, between them, behind mirrors).
std::vector<Ray> probeRays(const Scene& scene, float time, size_t n) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const View view(scene.camera(), ivec2(320, 240));
  const Bounds3 bounds = scene.bounds(time);
  std::vector<Ray> rays;
  rays.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    if (i % 2 == 0) {
      rays.push_back(view.primaryRay(unit(rng) * 320.0f, unit(rng) * 240.0f));
      continue;
    }
    Ray ray;
    ray.origin = glm::mix(bounds.lo, bounds.hi, vec3(unit(rng), unit(rng), unit(rng)));
    const float z = 2.0f * unit(rng) - 1.0f, phi = 2.0f * kPi * unit(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    ray.direction = vec3(r * std::cos(phi), r * std::sin(phi), z);
    rays.push_back(ray);
  }
  return rays;
}

class RaySceneUpdate : public ::testing::TestWithParam<const char*> {};

TEST_P(RaySceneUpdate, AnUpdatedSceneTracesWhatAFreshBuildTraces) {
  const Scene scene = makeBuiltinScene(GetParam());
  ASSERT_GT(scene.duration(), 0.0f) << "the scene must move for this test to mean anything";
  const float last = 0.8f * scene.duration();
  RayScene updated(scene);
  for (float time : {0.0f, 0.37f, 1.1f, 0.5f * scene.duration(), last}) {
    EXPECT_GT(updated.build(time), 0.0) << "at " << time << " s the triangles moved";
    EXPECT_EQ(updated.builtTime(), time);
  }
  RayScene fresh(scene);
  fresh.build(last);

  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const int instance = int(i);
    EXPECT_EQ(updated.instanceMatrix(instance), fresh.instanceMatrix(instance));
    EXPECT_EQ(updated.worldPositions(instance), fresh.worldPositions(instance));
  }

  const std::vector<Ray> rays = probeRays(scene, last, 20000);
  std::vector<RayHit> got(rays.size()), want(rays.size());
  updated.intersect(rays.data(), got.data(), rays.size());
  fresh.intersect(rays.data(), want.data(), rays.size());
  int hits = 0, differing = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const RayHit &g = got[i], &w = want[i];
    hits += w.hit();
    // Both BVHs hold the very same triangles, so the nearest hit is the same one; only the
    // triangle test's precomputed form may differ between BVH layouts: t to 1e-5 relative.
    const bool same = g.instance == w.instance && g.primitive == w.primitive &&
                      (!w.hit() || std::abs(g.t - w.t) <= 1e-5f * std::max(1.0f, w.t));
    if (!same && ++differing <= 5)
      ADD_FAILURE() << "ray " << i << ": updated scene hits instance " << g.instance << " triangle "
                    << g.primitive << " at t " << g.t << ", a fresh build instance " << w.instance
                    << " triangle " << w.primitive << " at t " << w.t;
  }
  EXPECT_EQ(differing, 0) << "rays of " << rays.size() << " that differ";
  EXPECT_GT(hits, int(rays.size()) / 2) << "most probe rays must hit something";
}

// Rigid motion (the teapot turns, the box slides), a deforming mirror, nine orbiting mirrors.
INSTANTIATE_TEST_SUITE_P(AnimatedScenes, RaySceneUpdate,
                         ::testing::Values("mirror-room", "ripple-pool", "spheres9"));

TEST(RaySceneUpdate, AStillSceneIsBuiltOnce) {
  const Scene scene = makeBuiltinScene("sphere-over-checker");
  RayScene rays(scene);
  EXPECT_GT(rays.build(0.0f), 0.0);
  // Nothing moves: no later time builds again (a moving light alone keeps the BVH).
  EXPECT_EQ(rays.build(1.0f), 0.0);
  EXPECT_EQ(rays.builtTime(), 1.0f);
}

}  // namespace
}  // namespace mirage
