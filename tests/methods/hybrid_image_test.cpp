// The hybrid method on the GPU: images against the ray tracer with stated tolerances, culling
// that never changes the image (it is conservative), rigid motion with the same kd-trees,
// second projections inside one C3RC on a concave reflector, and bad input. On failure the
// actual/expected/diff images are written under build/<preset>/test-artifacts/.
#include <gtest/gtest.h>

#include "methods/frame.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/scenes.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

class HybridImages : public GlTest {};

Scene objectsOnly() {
  return teapotSphereObjectsOnly();
}

const std::map<std::string, std::string> kDense = {{"points", "400000"}};

TEST_F(HybridImages, ReflectsNearbyObjectsBetterThanEnvironmentMaps) {
  const Scene scene = objectsOnly();
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{360, 256};
  RenderPair hybrid = renderWithTruth(scene, "hybrid", size, settings, kDense, 0.0f, kMatchedSsaa);
  RenderPair envmap = renderWithTruth(scene, "envmap", size, settings, {}, 0.0f, kMatchedSsaa);
  std::printf("reflector PSNR: hybrid %.2f dB, envmap %.2f dB\n", reflectorPsnr(hybrid),
              reflectorPsnr(envmap));
  // Measured at 360x256 with 400,000 points under matched 2x2 sampling: 32.3 dB (hybrid, level of
  // detail auto; 31.6 before the normal cones dropped the teapot's far side from its budget) vs
  // 21.4 dB (envmap); splats sized in whole output pixels, as at native resolution.
  EXPECT_TRUE(psnrAtLeast(hybrid.gpu, hybrid.cpu, floors::kHybridObjects, &hybrid.cpu_ids));
  EXPECT_GT(reflectorPsnr(hybrid), reflectorPsnr(envmap) + 10.0);
}

TEST_F(HybridImages, TheEnvironmentShowsWithItsParallax) {
  // A mirror sphere over a checkered floor and nothing else: the floor is the environment layer
  // (scene/layers.h), never points, and hybrid shows it through its background probe looked up
  // through the box of what the probe shows, open above (no geometry there): the floor where
  // the ray meets it, as envmap-box places it, and the sky along the ray's own direction. A
  // lookup by direction alone (envmap, hybrid's before the layers) shows the floor where the
  // probe's centre sees it.
  const Scene scene = spheresOverFloor(/*floor_only=*/true);
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{240, 180};
  RenderPair hybrid = renderWithTruth(scene, "hybrid", size, settings, {}, 0.0f, kMatchedSsaa);
  RenderPair box = renderWithTruth(scene, "envmap-box", size, settings, {}, 0.0f, kMatchedSsaa);
  RenderPair centre = renderWithTruth(scene, "envmap", size, settings, {}, 0.0f, kMatchedSsaa);
  EXPECT_EQ(hybrid.stats.at("points"), 0.0);  // the floor is not point-sampled
  std::printf("floor reflector PSNR: hybrid %.2f dB, envmap-box %.2f dB, envmap %.2f dB\n",
              reflectorPsnr(hybrid), reflectorPsnr(box), reflectorPsnr(centre));
  EXPECT_TRUE(psnrAtLeast(hybrid.gpu, hybrid.cpu, floors::kHybridFloorThroughTheBox,
                          &hybrid.cpu_ids));
  EXPECT_GT(reflectorPsnr(hybrid), reflectorPsnr(centre) + 10.0);
}

Image renderWith(FrameRenderer& renderer, const Scene& scene, ivec2 size,
                 const std::map<std::string, std::string>& params, float time = 0.0f,
                 std::map<std::string, double>* stats = nullptr) {
  FrameSettings settings;
  settings.order = 1;
  auto m = renderer.createMethod("hybrid", params, settings);
  renderer.render(*m, View(scene.camera(), size), time, settings);
  if (stats) *stats = m->stats();
  return renderer.read().color;
}

size_t differingPixels(const Image& a, const Image& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.pixelCount(); ++i) n += a.pixels()[i] != b.pixels()[i] ? 1 : 0;
  return n;
}

TEST_F(HybridImages, CullingIsConservativeTheImageDoesNotChange) {
  // Every culling mode projects every point that has a projection, so the frames are equal bit
  // for bit; the naive baseline projects every point through every C3RC (and drops no node for
  // its points facing away: the other modes do, normal_cone.h).
  const Scene scene = objectsOnly();
  const ivec2 size{200, 140};
  FrameRenderer renderer(scene, size);
  // Every point (no level of detail): the modes keep different points, which the subsample's
  // stride depends on.
  const std::map<std::string, std::string> base = {{"points", "20000"}, {"hybrid-lod", "0"}};
  std::map<std::string, double> exact, inner, hull, none;
  auto with = [&](const char* mode, std::map<std::string, double>* stats) {
    auto p = base;
    p["hybrid-culling"] = mode;
    return renderWith(renderer, scene, size, p, 0.0f, stats);
  };
  const Image a = with("exact", &exact), b = with("hull", &hull), c = with("none", &none);
  const Image d = with("inner", &inner);
  EXPECT_EQ(differingPixels(a, b), 0u);
  EXPECT_EQ(differingPixels(a, c), 0u);
  EXPECT_EQ(differingPixels(a, d), 0u);
  EXPECT_GT(exact.at("cull_cone_rejects"), 0.0) << "the closed teapot's far side";
  EXPECT_EQ(none.at("cull_cone_rejects"), 0.0);
  EXPECT_EQ(exact.at("projections"), none.at("projections"));
  EXPECT_GT(exact.at("projections"), 1000.0);
  EXPECT_LT(exact.at("points_projected"), 0.2 * none.at("points_projected"))
      << "the culling must spare most projections";
  EXPECT_LE(exact.at("points_projected"), inner.at("points_projected"));
  EXPECT_LE(inner.at("points_projected"), hull.at("points_projected"));
}

// Where the C3RCs' view volumes fold (concave reflectors: most of concave-dish's and glass's
// C3RCs), the exact test keeps the boxes a fold surface crosses, so the three modes still
// project the same points into the same frame, and the GPU culling (the same shared test) too.
TEST_F(HybridImages, CullingModesGiveTheSameFrameWhereViewVolumesFold) {
  const std::vector<std::pair<std::string, std::string>> cases = {{"concave-dish", "0"},
                                                                  {"glass", "20000"}};
  for (const auto& [name, points] : cases) {
    SCOPED_TRACE(name);
    const Scene scene = makeBuiltinScene(name);
    const ivec2 size{360, 256};
    FrameRenderer renderer(scene, size);
    std::map<std::string, double> stats[5];
    Image frames[5];
    const char* modes[5][2] = {
        {"exact", "cpu"}, {"hull", "cpu"}, {"none", "cpu"}, {"exact", "gpu"}, {"inner", "gpu"}};
    for (int i = 0; i < 5; ++i)
      frames[i] = renderWith(renderer, scene, size,
                             {{"points", points},
                              {"hybrid-culling", modes[i][0]},
                              {"hybrid-cull-on", modes[i][1]},
                              {"hybrid-lod", "0"}},
                             0.0f, &stats[i]);
    std::printf(
        "%s: %.0f of %.0f C3RCs fold, %.0f nodes kept for a fold; pairs with a "
        "projection: exact %.0f, hull %.0f, none %.0f\n",
        name.c_str(), stats[0].at("c3rcs_multiple"), stats[0].at("c3rcs"),
        stats[0].at("cull_fold_keeps"), stats[0].at("points_with_projection"),
        stats[1].at("points_with_projection"), stats[2].at("points_with_projection"));
    EXPECT_GT(stats[0].at("c3rcs_multiple"), 0.5 * stats[0].at("c3rcs"));
    EXPECT_GT(stats[0].at("projections"), 10000.0);
    for (int i = 1; i < 5; ++i) {
      SCOPED_TRACE(std::string(modes[i][0]) + " on " + modes[i][1]);
      EXPECT_EQ(differingPixels(frames[0], frames[i]), 0u);
      EXPECT_EQ(stats[0].at("points_with_projection"), stats[i].at("points_with_projection"));
      EXPECT_EQ(stats[0].at("projections"), stats[i].at("projections"));
    }
  }
}

TEST_F(HybridImages, RigidMotionKeepsTheTreesAndStaysCorrect) {
  Scene scene = objectsOnly();
  const int teapot = instanceNamed(scene, "teapot");
  ASSERT_GE(teapot, 0);
  Instance& inst = scene.instances[size_t(teapot)];
  Transform moved = inst.transform;
  moved.translation += vec3(0.25f, 0.0f, 0.35f);
  moved.rotation = glm::angleAxis(glm::radians(50.0f), vec3(0, 1, 0)) * inst.transform.rotation;
  inst.animation.keys = {{0.0f, inst.transform}, {1.0f, moved}};
  const ivec2 size{240, 160};
  FrameSettings settings;
  settings.order = 1;
  FrameRenderer renderer(scene, size);
  auto m = renderer.createMethod("hybrid", kDense, settings);
  const View view(scene.camera(), size);
  renderer.render(*m, view, 0.0f, settings);
  const double build_ms = m->stats().at("kd_build_ms");
  renderer.render(*m, view, 1.0f, settings);
  EXPECT_EQ(m->stats().at("kd_build_ms"), build_ms) << "no kd-tree is rebuilt for rigid motion";
  const Image after = displayed(renderer.read().color);
  RenderPair fresh = renderWithTruth(scene, "hybrid", size, settings, kDense, 1.0f);
  EXPECT_EQ(differingPixels(after, fresh.gpu), 0u) << "equal to a fresh build at t = 1";
  // Measured: 27.9 dB.
  EXPECT_TRUE(psnrAtLeast(after, fresh.cpu, floors::kHybridMovedVsTruth, &fresh.cpu_ids));
}

// Points of closed objects that face away from a whole reflector triangle are skipped before
// the cubic; they are hidden, so the frame stays as close to the ray tracer. An open surface
// (a cup) keeps all of its points: its inside shows.
TEST_F(HybridImages, BackFacingPointsOfClosedObjectsAreSkipped) {
  const Scene scene = objectsOnly();
  const ivec2 size{360, 256};
  FrameRenderer renderer(scene, size);
  std::map<std::string, double> cull, keep;
  // Every point: the level of detail would take as many projecting points either way.
  std::map<std::string, std::string> every = kDense;
  every["hybrid-lod"] = "0";
  renderWith(renderer, scene, size, every, 0.0f, &cull);
  std::map<std::string, std::string> params = every;
  params["hybrid-backfaces"] = "keep";
  renderWith(renderer, scene, size, params, 0.0f, &keep);
  EXPECT_EQ(keep.at("points_facing_away"), 0.0);
  EXPECT_EQ(keep.at("cull_cone_rejects"), 0.0);
  // Skipped one by one in the splatting, and whole kd-nodes at once in the culling (normal
  // cones), which leaves fewer points to the splatting.
  EXPECT_GT(cull.at("points_facing_away"), 0.1 * cull.at("points_projected"));
  EXPECT_GT(cull.at("cull_cone_rejects"), 0.0);
  EXPECT_LT(cull.at("cull_points_kept"), 0.8 * keep.at("cull_points_kept"));
  EXPECT_LT(cull.at("projections"), 0.7 * keep.at("projections"));

  FrameSettings settings;
  settings.order = 1;
  RenderPair culled = renderWithTruth(scene, "hybrid", size, settings, every);
  RenderPair kept = renderWithTruth(scene, "hybrid", size, settings, params);
  std::printf("reflector PSNR: back faces culled %.2f dB, kept %.2f dB\n", reflectorPsnr(culled),
              reflectorPsnr(kept));
  EXPECT_GT(reflectorPsnr(culled), reflectorPsnr(kept) - 0.2);

  // An open cup (a lathe without a bottom cap) beside a mirror sphere: never culled.
  Scene cup = mirrorSphereInSky();
  const int mesh = addMesh(cup, procedural::lathe({{0.3f, 0.0f}, {0.35f, 0.4f}}, 32));
  const int material = addMaterial(cup, Material::diffuse("cup", {0.8f, 0.3f, 0.2f}));
  addInstance(cup, "cup", mesh, material, placeAt({1.2f, -0.2f, 0.6f}));
  FrameRenderer cup_renderer(cup, size);
  std::map<std::string, double> open;
  renderWith(cup_renderer, cup, size, {{"points", "20000"}}, 0.0f, &open);
  EXPECT_GT(open.at("projections"), 0.0);
  EXPECT_EQ(open.at("points_facing_away"), 0.0);
}

TEST_F(HybridImages, NoPointSampledObjectsShowsTheBackgroundOnly) {
  // Only a mirror sphere and the sky: zero points is a documented case, not an error.
  const Scene scene = mirrorSphereInSky();
  const ivec2 size{160, 120};
  FrameRenderer renderer(scene, size);
  std::map<std::string, double> stats;
  const Image img = renderWith(renderer, scene, size, {}, 0.0f, &stats);
  EXPECT_EQ(stats.at("points"), 0.0);
  EXPECT_EQ(stats.at("splats_written"), 0.0);
  RenderPair truth = renderWithTruth(scene, "hybrid", size, FrameSettings{1, true});
  EXPECT_TRUE(psnrAtLeast(truth.gpu, truth.cpu, floors::kHybridSkyOnly, &truth.cpu_ids));
}

// The coarse concave dish: its large C3RCs converge and then diverge, so near the eye's caustic
// one C3RC projects a point twice. Splatting every projection (the default) finds them and comes
// closer to the ray tracer than the first projection alone (the paper's one fragment per point).
TEST_F(HybridImages, ConcaveDishSplatsSecondProjectionsInsideOneC3rc) {
  const Scene scene = makeBuiltinScene("concave-dish");
  const ivec2 size{360, 256};
  FrameRenderer renderer(scene, size);
  std::map<std::string, double> all, first;
  renderWith(renderer, scene, size, {}, 0.0f, &all);
  renderWith(renderer, scene, size, {{"hybrid-projections", "first"}}, 0.0f, &first);
  std::printf("projections: all %.0f for %.0f (point, C3RC) pairs; first %.0f\n",
              all.at("projections"), all.at("points_with_projection"), first.at("projections"));
  EXPECT_GT(all.at("c3rcs_multiple"), 0.0);
  EXPECT_EQ(first.at("projections"), first.at("points_with_projection"));
  EXPECT_EQ(all.at("points_with_projection"), first.at("points_with_projection"));
  // Measured: 0.64 % more projections than pairs with one (20.5 vs 19.8 dB below).
  EXPECT_GT(all.at("projections"), 1.003 * all.at("points_with_projection"));

  FrameSettings settings;
  settings.order = 1;
  RenderPair with_all = renderWithTruth(scene, "hybrid", size, settings);
  RenderPair with_first =
      renderWithTruth(scene, "hybrid", size, settings, {{"hybrid-projections", "first"}});
  std::printf("reflector PSNR: all %.3f dB, first %.3f dB\n", reflectorPsnr(with_all),
              reflectorPsnr(with_first));
  EXPECT_GT(reflectorPsnr(with_all), reflectorPsnr(with_first) + 0.3);
}

// The level of detail projects a uniform subsample of a C3RC's kept points (about --hybrid-lod
// points with a projection per visible pixel of its triangle, from a probe of its items) with
// larger splats: far fewer projections, close to the full image.
TEST_F(HybridImages, LevelOfDetailProjectsFewerPointsAndStaysClose) {
  const Scene scene = objectsOnly();
  const ivec2 size{360, 256};
  FrameRenderer renderer(scene, size);
  std::map<std::string, double> full, lod;
  std::map<std::string, std::string> every = kDense;
  every["hybrid-lod"] = "0";
  renderWith(renderer, scene, size, every, 0.0f, &full);
  std::map<std::string, std::string> params = kDense;
  params["hybrid-lod"] = "2";
  renderWith(renderer, scene, size, params, 0.0f, &lod);
  std::printf("projected: every point %.0f (%.0f with a projection), --hybrid-lod 2 %.0f (%.0f)\n",
              full.at("points_projected"), full.at("points_with_projection"),
              lod.at("points_projected"), lod.at("points_with_projection"));
  EXPECT_EQ(full.at("lod_points"), full.at("cull_points_kept"));
  EXPECT_EQ(full.at("points_projected"), full.at("cull_points_kept"));
  EXPECT_EQ(full.at("lod_probe_points"), 0.0);
  EXPECT_EQ(lod.at("cull_points_kept"), full.at("cull_points_kept"));
  EXPECT_GT(lod.at("lod_probe_points"), 0.0);
  EXPECT_LT(lod.at("points_projected"), 0.5 * full.at("points_projected"));
  EXPECT_LT(lod.at("points_with_projection"), 0.5 * full.at("points_with_projection"));

  FrameSettings settings;
  settings.order = 1;
  RenderPair pair = renderWithTruth(scene, "hybrid", size, settings, params);
  std::printf("reflector PSNR with --hybrid-lod 2: %.2f dB\n", reflectorPsnr(pair));
  EXPECT_TRUE(psnrAtLeast(pair.gpu, pair.cpu, floors::kHybridLod, &pair.cpu_ids));
}

TEST(HybridCli, BadParametersExitWithTheAllowedRange) {
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"--points 5000000", "--points"},
      {"--points -1", "--points"},
      {"--kd-leaf-points 2", "--kd-leaf-points"},
      {"--hybrid-culling fastest", "--hybrid-culling"},
      {"--hybrid-cull-on fpga", "--hybrid-cull-on"},
      {"--hybrid-projections some", "--hybrid-projections"},
      {"--splat-size 9", "--splat-size"},
      {"--kd-min-size 2", "--kd-min-size"},
      {"--hybrid-lod -1", "--hybrid-lod"},
      {"--hybrid-lod often", "--hybrid-lod"},
      {"--hybrid-lod 2e6", "--hybrid-lod"},
  };
  for (const Case& c : cases) {
    const CliResult r = runMirage("render --scene teapot-sphere --method hybrid --size 32x32 -o " +
                                  (testTempDir("hybrid-cli") / "bad.png").string() + " " + c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("allowed"), std::string::npos) << c.args << "\n" << r.output;
  }
}

// auto (the default) is 8 points a pixel with the CPU culling and every point with the GPU
// traversal; a density with the GPU traversal is an error.
TEST_F(HybridImages, LevelOfDetailAutoIsEightWithCpuCullingAndOffOnTheGpu) {
  const Scene scene = objectsOnly();
  const ivec2 size{200, 140};
  FrameRenderer renderer(scene, size);
  std::map<std::string, double> autos, eight, gpu;
  const Image a = renderWith(renderer, scene, size, kDense, 0.0f, &autos);
  std::map<std::string, std::string> p = kDense;
  p["hybrid-lod"] = "8";
  const Image b = renderWith(renderer, scene, size, p, 0.0f, &eight);
  EXPECT_EQ(autos.at("points_projected"), eight.at("points_projected"));
  EXPECT_LT(autos.at("points_projected"), autos.at("cull_points_kept"));
  EXPECT_TRUE(mostPixelsWithin(b, a, 0.0f, 0.0, nullptr, "lod-auto"));
  // The GPU traversal's auto projects what the CPU culling keeps with every point.
  p = kDense;
  p["hybrid-cull-on"] = "gpu";
  renderWith(renderer, scene, size, p, 0.0f, &gpu);
  EXPECT_EQ(gpu.at("points_projected"), autos.at("cull_points_kept"));
}

TEST(HybridCli, LevelOfDetailWithGpuCullingIsAClearError) {
  const CliResult r = runMirage(
      "render --scene teapot-sphere --method hybrid --size 32x32 --hybrid-lod 4 "
      "--hybrid-cull-on gpu -o " +
      (testTempDir("hybrid-cli") / "lod-gpu.png").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--hybrid-cull-on cpu"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace mirage::test
