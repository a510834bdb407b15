// Methods redo only what a change touches, and their frame counts prove it: a camera move redoes
// nothing; one diffuse object moving and turning re-captures its own billboards and re-shades its
// own depth maps but not the others', redraws no depth map and rebuilds no SRDM (rigid motion
// carries a map's camera with its object) and no hybrid background, while probes and the ray
// tracer's BVH follow it; a moving light re-shades the diffuse captures and keeps every depth
// map, SRDM and BVH.
#include <gtest/gtest.h>

#include "methods/frame.h"
#include "support/gl_test.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class DynamicCounts : public GlTest {};

using Counts = std::map<std::string, double>;

double count(const Counts& c, const std::string& name) {
  auto it = c.find(name);
  EXPECT_NE(it, c.end()) << "no count " << name;
  return it == c.end() ? -1.0 : it->second;
}

// teapot-sphere with the torus sliding sideways and turning (1 unit and 60° over 2 s) or, when
// `light_moves`, with a light that turns instead.
Scene movingTeapotSphere(bool light_moves) {
  Scene s = makeBuiltinScene("teapot-sphere");
  if (light_moves) {
    const vec3 d = s.light.direction;
    s.light.keys = {{0.0f, d, s.light.color},
                    {2.0f, glm::angleAxis(radians(40.0f), vec3(0, 1, 0)) * d, s.light.color}};
  } else {
    Instance& torus = s.instances[size_t(instanceNamed(s, "torus"))];
    Transform moved = torus.transform;
    moved.translation.x += 1.0f;
    moved.rotation = glm::angleAxis(radians(60.0f), vec3(0, 1, 0)) * moved.rotation;
    torus.animation.keys = {{0.0f, torus.transform}, {2.0f, moved}};
  }
  s.validate();
  return s;
}

struct Frames {
  Counts still, camera_moved, scene_moved;
  std::map<std::string, double> stats;
};

Frames threeFrames(const Scene& scene, const std::string& method,
                   const std::map<std::string, std::string>& params = {}) {
  FrameRenderer renderer(scene, {96, 72});
  FrameSettings settings;
  settings.order = 1;
  auto m = renderer.createMethod(method, params, settings);
  const CameraDesc cam = scene.camera();
  CameraDesc moved = cam;
  moved.position += vec3(0.3f, 0.1f, 0.0f);
  Frames f;
  renderer.render(*m, View(cam, {96, 72}), 0.0f, settings);
  renderer.render(*m, View(cam, {96, 72}), 0.0f, settings, nullptr, &f.still);
  renderer.render(*m, View(moved, {96, 72}), 0.0f, settings, nullptr, &f.camera_moved);
  renderer.render(*m, View(moved, {96, 72}), 1.0f, settings, nullptr, &f.scene_moved);
  f.stats = m->stats();
  return f;
}

void expectAllZero(const Counts& counts, const std::vector<std::string>& names,
                   const std::string& what) {
  for (const std::string& n : names) EXPECT_EQ(count(counts, n), 0.0) << what << ": " << n;
}

TEST_F(DynamicCounts, OneObjectMovingRedoesOnlyWhatShowsIt) {
  const Scene scene = movingTeapotSphere(false);
  {
    const Frames f = threeFrames(scene, "envmap");
    expectAllZero(f.still, {"cube_captures"}, "envmap, still");
    expectAllZero(f.camera_moved, {"cube_captures"}, "envmap, camera");
    EXPECT_EQ(count(f.scene_moved, "cube_captures"), 1.0);  // the one probe sees the torus
  }
  {
    const Frames f = threeFrames(scene, "billboard");
    expectAllZero(f.camera_moved, {"billboard_captures", "environment_captures"}, "billboard");
    const double all = f.stats.at("diffuse_billboards") + f.stats.at("reflective_billboards");
    const double moved = count(f.scene_moved, "billboard_captures");
    EXPECT_GE(moved, 1.0);  // the torus's
    EXPECT_LT(moved, all);  // and not the teapot's, the floor's or the sphere's
  }
  {
    const Frames f = threeFrames(scene, "depthmap");
    const std::vector<std::string> names = {"depthmap_color_captures", "depthmap_depth_captures",
                                            "srdm_builds"};
    expectAllZero(f.camera_moved, names, "depthmap, camera");
    // The torus turned, so the light falls on it from another side in its own space: its maps
    // are re-shaded; the teapot's are kept.
    const double moved = count(f.scene_moved, "depthmap_color_captures");
    EXPECT_GE(moved, 1.0);
    EXPECT_LT(moved, f.stats.at("depth_maps"));
    // A rigid motion carries the maps' cameras: no depth map is redrawn, no SRDM rebuilt.
    expectAllZero(f.scene_moved, {"depthmap_depth_captures", "srdm_builds"}, "depthmap, moved");
  }
  {
    const Frames f = threeFrames(scene, "hybrid");
    expectAllZero(f.camera_moved, {"background_captures"}, "hybrid, camera");
    // The torus is point-sampled: its kd-tree is in its own space, the background holds only
    // the floor, the other reflectors and the sky.
    expectAllZero(f.scene_moved, {"background_captures"}, "hybrid, moved");
    EXPECT_GT(count(f.scene_moved, "points_projected"), 0.0);
  }
  {
    const Frames f = threeFrames(scene, "raytrace");
    expectAllZero(f.camera_moved, {"bvh_builds"}, "raytrace, camera");
    EXPECT_EQ(count(f.scene_moved, "bvh_builds"), 1.0);
    EXPECT_EQ(count(f.scene_moved, "primary_rays"), 96.0 * 72.0);
  }
}

TEST_F(DynamicCounts, MovingLightReshadesDiffuseCapturesAndKeepsGeometry) {
  const Scene scene = movingTeapotSphere(true);
  {
    const Frames f = threeFrames(scene, "billboard");
    // Every diffuse billboard is re-shaded, no reflective one (they hold normals, not colour).
    EXPECT_EQ(count(f.scene_moved, "billboard_captures"), f.stats.at("diffuse_billboards"));
  }
  {
    const Frames f = threeFrames(scene, "depthmap");
    EXPECT_GE(count(f.scene_moved, "depthmap_color_captures"), 2.0);  // teapot's and torus's
    expectAllZero(f.scene_moved, {"depthmap_depth_captures", "srdm_builds"}, "depthmap, light");
  }
  {
    const Frames f = threeFrames(scene, "raytrace");
    expectAllZero(f.scene_moved, {"bvh_builds"}, "raytrace, light");  // same triangles
  }
  {
    const Frames f = threeFrames(scene, "hybrid");
    EXPECT_EQ(count(f.scene_moved, "background_captures"), 1.0);  // the floor is re-lit
  }
}

// A lone rippling mirror changes its own surface only: its probes (drawn without it) show
// nothing new, so no probe-based method re-captures, while the ray tracer re-builds its BVH.
// A second mirror sees the first: then the ripple is re-captured.
TEST_F(DynamicCounts, DeformingReflectorIsRecapturedWhereItShows) {
  Scene scene = makeBuiltinScene("ripple-pool");
  const Frames f = threeFrames(scene, "raytrace");
  EXPECT_EQ(count(f.scene_moved, "bvh_builds"), 1.0);
  for (const char* method : {"envmap", "hybrid", "zexel"}) {
    const Frames m = threeFrames(scene, method);
    const char* counter = std::string(method) == "envmap"   ? "cube_captures"
                          : std::string(method) == "hybrid" ? "background_captures"
                                                            : "zexel_cube_captures";
    expectAllZero(m.scene_moved, {counter}, std::string(method) + ", lone ripple");
  }
  // A mirror ball beside the pool: each now sees the other.
  const int ball = addMesh(scene, procedural::sphere(0.3f, 32, 16));
  addInstance(scene, "mirror-ball", ball, addMaterial(scene, Material::mirror("ball")),
              placeAt({1.2f, 0.5f, 0.8f}));
  scene.validate();
  // Only the ball's probe shows the rippling pool: the pool's own probe shows the ball, at its
  // base colour at order 1, and nothing else that moved (no budget: every probe that drifted).
  const std::map<std::string, std::string> all = {{"probe-budget", "0"}};
  EXPECT_EQ(count(threeFrames(scene, "envmap", all).scene_moved, "cube_captures"), 1.0);
  EXPECT_EQ(count(threeFrames(scene, "zexel", all).scene_moved, "zexel_cube_captures"), 1.0);
}

}  // namespace
}  // namespace mirage::test
