// The hybrid method's splats: their size under an object's non-uniform scale (the shared
// hybrid_world_spacing against analytic stretches, and a stretched object reflected without
// holes whichever of its axes the scale stretches), and their visibility order at the largest
// point count (distinct depths stay ordered at 4,000,000 points).
#include <gtest/gtest.h>

#include <cstdio>

#include "methods/frame.h"
#include "methods/hybrid/hybrid_shared.h"
#include "support/gl_test.h"
#include "support/render_pair.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

namespace sh = shading;

TEST(HybridSplatSize, WorldSpacingIsTheLargestStretchWithinTheTangentPlane) {
  const mat3 stretch_y(vec3(1, 0, 0), vec3(0, 4, 0), vec3(0, 0, 1));  // columns: diag(1, 4, 1)
  // The tangent plane of a point facing z holds y: stretched 4x; facing y, it holds x and z.
  EXPECT_NEAR(sh::hybrid_world_spacing(stretch_y, {0, 0, 1}, 0.5f), 2.0f, 1e-5f);
  EXPECT_NEAR(sh::hybrid_world_spacing(stretch_y, {0, 1, 0}, 0.5f), 0.5f, 1e-5f);
  EXPECT_NEAR(sh::hybrid_world_spacing(stretch_y, {0, 0, -3}, 0.5f), 2.0f, 1e-5f)
      << "any length, either sign";
  // Facing (1, 1, 0)/√2: the plane holds z (stretch 1) and (1, −1, 0)/√2 (stretch √(17/2)).
  EXPECT_NEAR(sh::hybrid_world_spacing(stretch_y, {1, 1, 0}, 1.0f), std::sqrt(8.5f), 1e-4f);
  // A uniform scale s after any rotation: s, whatever the normal.
  const mat3 turned = mat3(glm::rotate(mat4(1.0f), 0.7f, glm::normalize(vec3(1, 2, 3)))) * 3.0f;
  for (const vec3& n : {vec3(1, 0, 0), vec3(0.3f, -0.5f, 0.8f), vec3(0, 0, 1)})
    EXPECT_NEAR(sh::hybrid_world_spacing(turned, n, 0.25f), 0.75f, 1e-5f);
  // A rotation after the stretch moves the stretched direction, not its size.
  const mat3 rotated_stretch = mat3(glm::rotate(mat4(1.0f), 1.1f, vec3(0, 0, 1))) * stretch_y;
  EXPECT_NEAR(sh::hybrid_world_spacing(rotated_stretch, {0, 0, 1}, 0.5f), 2.0f, 1e-5f);
  // A shear: its largest stretch in the plane z = 0 is the larger singular value of
  // [[1, 1], [0, 1]], the golden ratio.
  const mat3 shear(vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 0, 1));
  EXPECT_NEAR(sh::hybrid_world_spacing(shear, {0, 0, 1}, 1.0f), (1.0f + std::sqrt(5.0f)) / 2.0f,
              1e-5f);
  // No normal: the Frobenius norm, at least every stretch.
  EXPECT_NEAR(sh::hybrid_world_spacing(stretch_y, vec3(0.0f), 1.0f), std::sqrt(18.0f), 1e-5f);
}

class HybridSplats : public GlTest {};

// A thin ellipsoid (a sphere of radius 0.2 stretched 5x along world y) standing over a mirror
// floor, seen in it; the stretch made either by scaling the object's y axis, or by scaling its x
// axis and turning it 90° about z. The object is the same; the model matrices differ.
Scene stretchedOverMirror(bool through_x) {
  Scene s;
  s.name = "stretched-over-mirror";
  const int floor = addMesh(s, procedural::quad(6.0f, 6.0f));
  addInstance(s, "mirror", floor, addMaterial(s, Material::mirror("mirror")), {});
  const int sphere = addMesh(s, procedural::sphere(0.2f, 48, 24));
  const int red = addMaterial(s, Material::diffuse("red", {0.9f, 0.2f, 0.1f}));
  const Transform t = through_x ? placeAt({0.0f, 1.2f, 0.0f}, {5.0f, 1.0f, 1.0f},
                                          glm::angleAxis(glm::radians(90.0f), vec3(0, 0, 1)))
                                : placeAt({0.0f, 1.2f, 0.0f}, {1.0f, 5.0f, 1.0f});
  addInstance(s, "ellipsoid", sphere, red, t);
  finishScene(s, vec3{0.0f, 1.0f, 3.0f}, vec3{0.0f, -0.6f, 0.0f}, 50.0f);
  return s;
}

// The object's pixels in the reflection of the ray tracer's frame (its red: red well above green
// and blue, on a reflector pixel), and how many of them the method's frame shows without it:
// holes between the splats.
struct Holes {
  int object = 0, holes = 0;
};

bool reddish(const vec4& c) {
  return c.x > c.y + 0.2f && c.x > c.z + 0.2f;
}

Holes holesIn(const RenderPair& p) {
  Holes h;
  for (size_t i = 0; i < p.cpu.pixelCount(); ++i) {
    if (p.cpu_ids.pixels()[i] == 0 || !reddish(p.cpu.pixels()[i])) continue;
    ++h.object;
    h.holes += reddish(p.gpu.pixels()[i]) ? 0 : 1;
  }
  return h;
}

TEST_F(HybridSplats, ANonUniformScaleLeavesNoHolesWhicheverAxisItStretches) {
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{240, 240};
  const std::map<std::string, std::string> params = {{"points", "3000"}};
  Holes holes[2];
  for (int through_x = 0; through_x < 2; ++through_x) {
    const RenderPair p =
        renderWithTruth(stretchedOverMirror(through_x), "hybrid", size, settings, params);
    holes[through_x] = holesIn(p);
    std::printf(
        "stretched through %s: %d of %d object pixels show no point, reflector PSNR "
        "%.2f dB\n",
        through_x ? "x" : "y", holes[through_x].holes, holes[through_x].object, reflectorPsnr(p));
    EXPECT_GT(p.stats.at("projections"), 500.0);
  }
  EXPECT_GT(holes[0].object, 1000) << "the reflection shows the object";
  for (int k = 0; k < 2; ++k) EXPECT_LT(holes[k].holes, holes[k].object / 50);
}

TEST(HybridDepthKey, DistinctPushBacksKeepTheirOrder) {
  // Neighbouring floats across the push-backs a frame sees (any scene scale), and zero: the
  // keys order as the depths do, whatever the point count (no index shares the word).
  for (float x : {0.0f, 1e-30f, 1e-6f, 1e-3f, 0.37f, 1.0f, 3.3f, 1e3f, 1e6f, 3e38f}) {
    const float next = std::nextafter(x, 1e38f * 10.0f);
    EXPECT_LT(sh::hybrid_depth_key(x), sh::hybrid_depth_key(next)) << x;
    EXPECT_LT(sh::hybrid_depth_key(x), MIRAGE_HYBRID_EMPTY) << x;
  }
  EXPECT_EQ(sh::hybrid_depth_key(-1.0f), sh::hybrid_depth_key(0.0f)) << "clamped at zero";
  // A splat is a candidate when it is at least as near as its pixel's word was.
  EXPECT_TRUE(sh::hybrid_is_candidate(MIRAGE_HYBRID_EMPTY, sh::hybrid_depth_key(2.0f)));
  EXPECT_TRUE(sh::hybrid_is_candidate(sh::hybrid_depth_key(2.0f), sh::hybrid_depth_key(2.0f)));
  EXPECT_FALSE(sh::hybrid_is_candidate(sh::hybrid_depth_key(1.0f), sh::hybrid_depth_key(2.0f)));
}

// Two concentric spheres over a mirror floor, the inner (blue, first: its points take the lower
// indices) 0.02 inside the outer (red): 4,000,000 points in all, the most a 22-bit winner index
// names. The reflection must show the red one, 0.02 nearer the mirror everywhere it faces it:
// beyond the front's tolerance (MIRAGE_HYBRID_FRONT_TOLERANCE, 0.5 % of push-back depths of at
// most 1.6 here), so no blue point is ever a candidate.
Scene nestedSpheresOverMirror() {
  Scene s;
  s.name = "nested-spheres-over-mirror";
  const int floor = addMesh(s, procedural::quad(2.0f, 2.0f));
  addInstance(s, "mirror", floor, addMaterial(s, Material::mirror("mirror")), {});
  const int blue = addMaterial(s, Material::diffuse("blue", {0.1f, 0.2f, 0.9f}));
  const int red = addMaterial(s, Material::diffuse("red", {0.9f, 0.2f, 0.1f}));
  addInstance(s, "inner", addMesh(s, procedural::sphere(0.38f, 96, 48)), blue,
              placeAt({0.0f, 0.8f, 0.0f}));
  addInstance(s, "outer", addMesh(s, procedural::sphere(0.4f, 96, 48)), red,
              placeAt({0.0f, 0.8f, 0.0f}));
  finishScene(s, vec3{0.0f, 0.9f, 2.2f}, vec3{0.0f, -0.3f, 0.0f}, 50.0f);
  return s;
}

TEST_F(HybridSplats, TheNearerOfTwoSurfacesWinsAtFourMillionPoints) {
  const Scene scene = nestedSpheresOverMirror();
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{200, 200};
  const RenderPair p = renderWithTruth(scene, "hybrid", size, settings,
                                       {{"points", "4000000"}, {"hybrid-lod", "0"}});
  int sphere = 0, blue = 0;
  for (size_t i = 0; i < p.cpu.pixelCount(); ++i) {
    if (p.cpu_ids.pixels()[i] == 0 || !reddish(p.cpu.pixels()[i])) continue;
    ++sphere;
    const vec4 c = p.gpu.pixels()[i];
    blue += c.z > c.x ? 1 : 0;
  }
  std::printf(
      "%d of %d pixels of the red sphere's reflection show the blue one (%.0f points, "
      "%.0f candidates)\n",
      blue, sphere, p.stats.at("points"), p.stats.at("splat_candidates"));
  EXPECT_EQ(p.stats.at("points"), 4000000.0);
  EXPECT_GT(sphere, 1000);
  EXPECT_LT(blue, sphere / 100);
}

// The candidate buffer starts at one record a pixel; a frame that appends more grows it and
// splats again: the same frame as the next one, which finds the buffer large enough (how many
// candidates a frame appends depends on the order the splats ran in; which one wins does not).
TEST_F(HybridSplats, MoreCandidatesThanTheBufferHoldsGrowItAndDropNothing) {
  const Scene scene = nestedSpheresOverMirror();
  const ivec2 size{16, 16};
  FrameRenderer renderer(scene, size);
  FrameSettings settings;
  settings.order = 1;
  auto m = renderer.createMethod("hybrid", {{"points", "100000"}, {"splat-size", "8"}}, settings);
  const View view(scene.camera(), size);
  renderer.render(*m, view, 0.0f, settings);
  const Image first = renderer.read().color;
  const double candidates = m->stats().at("splat_candidates");
  renderer.render(*m, view, 0.0f, settings);
  const Image second = renderer.read().color;
  std::printf("%.0f candidates for %d pixels\n", candidates, size.x * size.y);
  EXPECT_GT(candidates, double(size.x * size.y)) << "the first frame outgrew the buffer";
  size_t differing = 0;
  for (size_t i = 0; i < first.pixelCount(); ++i)
    differing += first.pixels()[i] != second.pixels()[i] ? 1 : 0;
  EXPECT_EQ(differing, 0u);
}

// The splatting pass keeps every invocation within the loop budget (gpu/loop_budget.h), so that
// llvmpipe's loop limiter never cuts it short (the host checks every pair was projected and
// throws otherwise). At the README's advise size (360x256 under --ssaa 4) the composite that
// draws gallery's reflectors each by hybrid, at the walk's 6 s view, projected 25,387 of its
// 29,209 pairs before the runs were sized by their worst case.
TEST_F(HybridSplats, TheAdviseCompositeAtTheReadmeSizeProjectsEveryPair) {
  const Scene scene = makeBuiltinScene("gallery");
  const ivec2 size = ivec2(360, 256) * 4;
  FrameSettings settings;
  settings.pixel_scale = 4;
  FrameRenderer renderer(scene, size);
  auto m = renderer.createMethod(
      "mixed",
      {{"assign",
        "mirror-back=hybrid;mirror-left=hybrid;mirror-sphere=hybrid;mirror-teapot=hybrid;"
        "concave-mirror=hybrid"}},
      settings);
  const CameraDesc walk = scene.camera("walk");
  EXPECT_NO_THROW(renderer.render(*m, View(walk.at(6.0f), size), 6.0f, settings));
}

// Every splat at the largest side a run plans for (--splat-size 8 under --ssaa 4: 32 frame
// pixels), every point, on the CPU culling's runs and on the GPU culling's slices of leaves of
// 4,096 points: every pair projected (the host's check), the same frame either way.
TEST_F(HybridSplats, RunsAtTheLargestSplatsStayWithinTheLoopBudget) {
  const Scene scene = nestedSpheresOverMirror();
  const ivec2 size = ivec2(48, 48) * 4;
  FrameSettings settings;
  settings.order = 1;
  settings.pixel_scale = 4;
  FrameRenderer renderer(scene, size);
  const View view(scene.camera(), size);
  std::vector<Image> frames;
  for (const char* cull : {"cpu", "gpu"}) {
    auto m = renderer.createMethod("hybrid",
                                   {{"points", "200000"},
                                    {"splat-size", "8"},
                                    {"hybrid-lod", "0"},
                                    {"kd-leaf-points", "4096"},
                                    {"hybrid-cull-on", cull}},
                                   settings);
    ASSERT_NO_THROW(renderer.render(*m, view, 0.0f, settings)) << cull;
    const auto stats = m->stats();
    EXPECT_GT(stats.at("points_projected"), 20000.0) << cull;
    frames.push_back(renderer.read().color);
  }
  EXPECT_TRUE(frames[0].pixels() == frames[1].pixels()) << "the CPU and GPU culling's frames";
}

}  // namespace
}  // namespace mirage::test
