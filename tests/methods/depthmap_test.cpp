// The depthmap method: its shared geometry (frustum clipping, the projective map between the
// projected and the 3-D ray, the brute-force walk) on the CPU, and on the GPU images against the
// ray tracer with stated tolerances, the rebuild rules (rigid motion rebuilds nothing; a light
// change re-captures colour only) and bad parameters. On failure the actual/expected/diff images
// are written under build/<preset>/test-artifacts/.
#include <gtest/gtest.h>

#include <random>

#include "methods/depthmap/depthmap_set.h"
#include "methods/depthmap/depthmap_shared.h"
#include "methods/frame.h"
#include "scene/builtin_scenes.h"
#include "scene/procedural.h"
#include "support/depth_camera.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/scenes.h"
#include "support/test_files.h"

namespace mirage::shading {
namespace {
thread_local const mirage::DepthMap* g_marched = nullptr;
}
inline float depthmap_depth(int, int x, int y) {
  return g_marched->at(x, y);
}
}  // namespace mirage::shading

#include "methods/depthmap/depthmap_march_shared.h"

// The map order of the shader (depthmap_maps_shared.h) over maps held by the test: each map's
// camera, depth and SRDMs, and the shader's search of one map on the CPU (clip to the frustum,
// project, one SRDM row, back to the ray).
namespace mirage::shading {
namespace {
struct TestMap {
  View view;
  Srdm srdm;
};
thread_local const std::vector<TestMap>* g_maps = nullptr;
thread_local Ray g_ray;
thread_local float g_hit_t = -1.0f;
}  // namespace
inline vec3 depthmap_axis(int map) {
  return (*g_maps)[size_t(map)].view.forward();
}
inline bool depthmap_try(int map) {
  const TestMap& m = (*g_maps)[size_t(map)];
  const mat4 vp = m.view.viewProjection();
  float t0 = 0.0f, t1 = 100.0f;
  if (!depthmap_clip(vp, g_ray.origin, g_ray.direction, t0, t1)) return false;
  const vec4 c0 = vp * vec4(g_ray.origin + t0 * g_ray.direction, 1.0f);
  const vec4 c1 = vp * vec4(g_ray.origin + t1 * g_ray.direction, 1.0f);
  const float w = float(m.srdm.size);
  const float lambda =
      intersectSrdm(m.srdm, depthmap_texel_point(c0, w), depthmap_texel_point(c1, w));
  if (lambda < 0.0f) return false;
  g_hit_t = t0 + depthmap_unproject_fraction(lambda, c0.w, c1.w) * (t1 - t0);
  return true;
}
}  // namespace mirage::shading

#include "methods/depthmap/depthmap_maps_shared.h"

namespace mirage::test {
namespace {

namespace sh = shading;

bool insideClip(const mat4& vp, vec3 p, float slack) {
  const vec4 c = vp * vec4(p, 1.0f);
  return std::abs(c.x) <= c.w + slack && std::abs(c.y) <= c.w + slack &&
         std::abs(c.z) <= c.w + slack;
}

TEST(DepthMapGeometry, ClipKeepsExactlyThePartInsideTheFrustum) {
  const View view = depthCamera(vec3(0.0f), 1.0f, vec3(0.3f, 0.2f, 1.0f), 20.0f, 64);
  const mat4 vp = view.viewProjection();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-8.0f, 8.0f);
  int clipped = 0;
  for (int i = 0; i < 4000; ++i) {
    const vec3 origin(u(rng), u(rng), u(rng));
    const vec3 dir = glm::normalize(vec3(u(rng), u(rng), u(rng)) * 0.2f - origin);
    float t0 = 0.0f, t1 = 100.0f;
    if (!sh::depthmap_clip(vp, origin, dir, t0, t1)) {
      // Nothing inside: sample the ray densely.
      for (int k = 1; k < 400; ++k)
        ASSERT_FALSE(insideClip(vp, origin + dir * (100.0f * float(k) / 400.0f), -1e-3f))
            << "ray " << i << " was discarded but passes through the frustum";
      continue;
    }
    ++clipped;
    for (int k = 1; k < 20; ++k) {
      const float t = t0 + (t1 - t0) * float(k) / 20.0f;
      ASSERT_TRUE(insideClip(vp, origin + dir * t, 1e-3f)) << "ray " << i << " at " << t;
    }
    const float eps = 1e-3f * (1.0f + t1);
    if (t0 > eps) {
      EXPECT_FALSE(insideClip(vp, origin + dir * (t0 - eps), -1e-4f));
    }
    if (t1 < 100.0f - eps) {
      EXPECT_FALSE(insideClip(vp, origin + dir * (t1 + eps), -1e-4f));
    }
  }
  EXPECT_GT(clipped, 200);
}

TEST(DepthMapGeometry, SphereTestAcceptsExactlyTheRaysThatMeetItInRange) {
  namespace sh = shading;
  const vec4 sphere(1.0f, 2.0f, 3.0f, 0.5f);
  const vec3 origin(1.0f, 2.0f, 0.0f), at(0.0f, 0.0f, 1.0f);  // straight at the centre: t 2.5..3.5
  EXPECT_TRUE(sh::depthmap_sphere_overlaps(origin, at, sphere, 0.0f, 100.0f));
  EXPECT_TRUE(sh::depthmap_sphere_overlaps(origin, at, sphere, 3.4f, 100.0f));
  EXPECT_FALSE(sh::depthmap_sphere_overlaps(origin, at, sphere, 3.6f, 100.0f));  // past it
  EXPECT_TRUE(sh::depthmap_sphere_overlaps(origin, at, sphere, 0.0f, 2.6f));
  EXPECT_FALSE(sh::depthmap_sphere_overlaps(origin, at, sphere, 0.0f, 2.4f));     // a nearer hit
  EXPECT_FALSE(sh::depthmap_sphere_overlaps(origin, -at, sphere, 0.0f, 100.0f));  // behind
  // Passing 0.49 from the centre meets it; 0.51 does not. A direction of any length.
  EXPECT_TRUE(sh::depthmap_sphere_overlaps(origin + vec3(0.49f, 0, 0), 3.0f * at, sphere, 0, 100));
  EXPECT_FALSE(sh::depthmap_sphere_overlaps(origin + vec3(0.51f, 0, 0), at, sphere, 0, 100));
  // From inside: always.
  EXPECT_TRUE(sh::depthmap_sphere_overlaps(vec3(sphere), vec3(0, 1, 0), sphere, 0.0f, 0.1f));
}

TEST(DepthMapGeometry, ProjectedFractionMapsBackToTheRay) {
  const View view = depthCamera(vec3(0.0f), 1.0f, vec3(0.0f, 0.0f, 1.0f), 30.0f, 64);
  const mat4 vp = view.viewProjection();
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-0.9f, 0.9f), f(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const vec4 ca = vp * vec4(a, 1.0f), cb = vp * vec4(b, 1.0f);
    const vec3 pa = sh::depthmap_texel_point(ca, 64.0f), pb = sh::depthmap_texel_point(cb, 64.0f);
    const float mu = f(rng);
    const vec3 p = sh::depthmap_texel_point(vp * vec4(glm::mix(a, b, mu), 1.0f), 64.0f);
    // lambda along the projected segment, from its longer axis.
    const vec2 d = vec2(pb) - vec2(pa);
    const int axis = std::abs(d.x) > std::abs(d.y) ? 0 : 1;
    if (std::abs(d[axis]) < 1.0f) continue;
    const float lambda = (p[axis] - pa[axis]) / d[axis];
    EXPECT_NEAR(sh::depthmap_unproject_fraction(lambda, ca.w, cb.w), mu, 2e-4f);
  }
}

TEST(DepthMapGeometry, LinearWalkFindsTheFrontOfATracedSphere) {
  // A sphere of radius 1 seen by the depth camera: rays through its centre along the camera's
  // axis reach its front at distance (camera distance - 1).
  Scene scene;
  scene.meshes.push_back(procedural::sphere(1.0f, 96, 48));
  scene.materials.push_back(Material::diffuse("grey", vec3(0.5f)));
  scene.instances.push_back({"sphere", 0, 0, {}, {}, {}, {}});
  const View view = depthCamera(vec3(0.0f), 1.0f, vec3(0.0f, 0.0f, 1.0f), 20.0f, 128);
  const DepthMap map = traceDepthMap(scene, 0, 0.0f, view);
  sh::g_marched = &map;
  const mat4 vp = view.viewProjection();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-0.6f, 0.6f);
  for (int i = 0; i < 200; ++i) {
    // From beside the camera towards a point on the sphere's front half.
    const vec3 target(u(rng), u(rng), 0.0f);
    const vec3 on_sphere(target.x, target.y, std::sqrt(1.0f - glm::dot(target, target)));
    const vec3 origin = view.eye() + vec3(u(rng), u(rng), 0.0f);
    const vec3 dir = glm::normalize(on_sphere - origin);
    float t0 = 0.0f, t1 = 100.0f;
    ASSERT_TRUE(sh::depthmap_clip(vp, origin, dir, t0, t1));
    const vec4 c0 = vp * vec4(origin + t0 * dir, 1.0f), c1 = vp * vec4(origin + t1 * dir, 1.0f);
    int examined = 0;
    const float lambda = sh::depthmap_march(0, 128, sh::depthmap_texel_point(c0, 128.0f),
                                            sh::depthmap_texel_point(c1, 128.0f), examined);
    ASSERT_GE(lambda, 0.0f) << "ray " << i;
    const float t = t0 + sh::depthmap_unproject_fraction(lambda, c0.w, c1.w) * (t1 - t0);
    // Within about a texel's depth step of the true hit.
    EXPECT_NEAR(t, glm::length(on_sphere - origin), 0.03f) << "ray " << i;
    EXPECT_GT(examined, 0);
  }
}

TEST(DepthMapSet, MapsAreTriedInOrderOfAlignmentWithTheRay) {
  // Six cameras around an object: a ray tries every map once, the camera looking most nearly
  // along it first.
  std::vector<sh::TestMap> maps;
  for (vec3 from : {vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0),
                    vec3(0, -1, 0)})
    maps.push_back({depthCamera(vec3(0.0f), 1.0f, from, 20.0f, 16), {}});
  sh::g_maps = &maps;
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 100; ++i) {
    const vec3 dir = glm::normalize(vec3(u(rng), u(rng), u(rng)));
    std::vector<int> order;
    for (int k = sh::depthmap_next_map(dir, 0, 6, -1); k >= 0;
         k = sh::depthmap_next_map(dir, 0, 6, k))
      order.push_back(k);
    ASSERT_EQ(order.size(), 6u);
    for (size_t k = 1; k < order.size(); ++k)
      EXPECT_GE(glm::dot(dir, maps[size_t(order[k - 1])].view.forward()),
                glm::dot(dir, maps[size_t(order[k])].view.forward()));
  }
}

TEST(DepthMapSet, ARayMissingTheBestAlignedMapFallsBackToTheNext) {
  // A unit sphere with maps from +z (map 0) and -z (map 1). A ray running almost sideways, a
  // little towards +z, enters the sphere at (-0.8, 0, 0.6), on the half map 0 sees: map 1
  // looks more nearly along the ray but sees the other half, behind which the ray passes.
  Scene scene;
  scene.meshes.push_back(procedural::sphere(1.0f, 96, 48));
  scene.materials.push_back(Material::diffuse("grey", vec3(0.5f)));
  scene.instances.push_back({"sphere", 0, 0, {}, {}, {}, {}});
  std::vector<sh::TestMap> maps;
  for (vec3 from : {vec3(0, 0, 1), vec3(0, 0, -1)}) {
    const View view = depthCamera(vec3(0.0f), 1.0f, from, 20.0f, 128);
    maps.push_back(
        {view, buildSrdm(traceDepthMap(scene, 0, 0.0f, view), {60, 16, SrdmSimplifier::kGreedy})});
  }
  sh::g_maps = &maps;
  const vec3 dir = glm::normalize(vec3(1.0f, 0.0f, 0.15f));
  sh::g_ray = Ray{vec3(-0.8f, 0.0f, 0.6f) - 3.0f * dir, dir};
  ASSERT_EQ(sh::depthmap_next_map(dir, 0, 2, -1), 1) << "map 1 looks more nearly along the ray";
  ASSERT_FALSE(sh::depthmap_try(1)) << "the best-aligned map misses";
  EXPECT_EQ(sh::depthmap_object_search(dir, 0, 2, 1), -1) << "the best map alone (no fallback)";
  sh::g_hit_t = -1.0f;
  EXPECT_EQ(sh::depthmap_object_search(dir, 0, 2, 2), 0) << "the next map is hit";
  EXPECT_NEAR(sh::g_hit_t, 3.0f, 0.05f) << "where the ray enters the sphere";
}

TEST(DepthMapSet, MapsFollowTheirObjectRigidly) {
  Scene scene = makeBuiltinScene("teapot-sphere");
  DepthMapOptions options;
  options.maps = 2;
  const std::vector<DepthMapSpec> specs = placeDepthMaps(scene, options);
  // The teapot and the torus (the floor is planar, the sphere a reflector), two maps each.
  ASSERT_EQ(specs.size(), 4u);
  EXPECT_EQ(depthMappedInstances(specs).size(), 2u);
  const DepthMapSpec& s = specs[0];
  const mat4 model = scene.instances[size_t(s.instance)].matrixAt(0.0f);
  Transform moved;
  moved.translation = vec3(0.7f, 0.1f, -0.4f);
  moved.rotation = glm::angleAxis(0.8f, glm::normalize(vec3(0.2f, 1.0f, 0.1f)));
  const mat4 motion = moved.matrix();
  const View a = depthMapView(s, model, options), b = depthMapView(s, motion * model, options);
  // A point of the object projects to the same texel and depth before and after the motion.
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(-0.3f, 0.3f);
  for (int i = 0; i < 100; ++i) {
    const vec3 p = transformPoint(model, s.centre + vec3(u(rng), u(rng), u(rng)));
    const vec4 ca = a.viewProjection() * vec4(p, 1.0f);
    const vec4 cb = b.viewProjection() * vec4(transformPoint(motion, p), 1.0f);
    const vec3 pa = sh::depthmap_texel_point(ca, 256.0f), pb = sh::depthmap_texel_point(cb, 256.0f);
    EXPECT_NEAR(pa.x, pb.x, 1e-2f);
    EXPECT_NEAR(pa.y, pb.y, 1e-2f);
    EXPECT_NEAR(pa.z, pb.z, 1e-5f);
  }
  // The second map looks from the other side.
  EXPECT_LT(glm::dot(specs[0].from, specs[1].from), -0.99f);
}

class DepthMapImages : public GlTest {};

TEST_F(DepthMapImages, ReflectsCurvedObjectsBetterThanBillboards) {
  const Scene scene = teapotSphereObjectsOnly();
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{360, 256};
  RenderPair depth = renderWithTruth(scene, "depthmap", size, settings, {}, 0.0f, kMatchedSsaa);
  RenderPair board = renderWithTruth(scene, "billboard", size, settings, {}, 0.0f, kMatchedSsaa);
  std::printf("reflector PSNR: depthmap %.2f dB, billboard %.2f dB\n", reflectorPsnr(depth),
              reflectorPsnr(board));
  // Measured at 360x256 under matched 2x2 sampling: 40.6 dB (depthmap) vs 26.5 dB (billboard)
  // (35.5 vs 26.0 at one sample a pixel).
  EXPECT_TRUE(psnrAtLeast(depth.gpu, depth.cpu, floors::kDepthmapObjects, &depth.cpu_ids));
  EXPECT_GT(reflectorPsnr(depth), reflectorPsnr(board) + 10.0);
}

TEST_F(DepthMapImages, SrdmSearchMatchesTheFullMapWalk) {
  // One SRDM row of 8 points against the walk over every texel of the full map: the same
  // reflections up to the simplification error at the objects' edges.
  const Scene scene = teapotSphereObjectsOnly();
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{360, 256};
  FrameRenderer renderer(scene, size);
  const View view(scene.camera(), size);
  auto srdm = renderer.createMethod("depthmap", {}, settings);
  renderer.render(*srdm, view, 0.0f, settings);
  const RenderedFrame a = renderer.read();
  auto linear = renderer.createMethod("depthmap", {{"depthmap-search", "linear"}}, settings);
  renderer.render(*linear, view, 0.0f, settings);
  const RenderedFrame b = renderer.read();
  const Image da = displayed(a.color), db = displayed(b.color);
  // Measured: 39.0 dB.
  EXPECT_TRUE(psnrAtLeast(da, db, floors::kDepthmapSrdmVsLinear, &a.ids));
}

TEST_F(DepthMapImages, TwoRowsRecoverCoarseAngularSteps) {
  // At n = 9 (20 degrees between domains) the row through the projected ray's midpoint departs
  // from oblique rays; each second-row search (--srdm-rows 2) must render its own image, closer
  // to the ray tracer than one row's. (The rays here are short: the gains are a fraction of a
  // dB, against 6-7 dB on the bunny close-up of docs/depthmap-results.md.)
  const Scene scene = teapotSphereObjectsOnly();
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{360, 256};
  auto psnr = [&](const std::map<std::string, std::string>& extra) {
    std::map<std::string, std::string> params{{"srdm-n", "9"}};
    params.insert(extra.begin(), extra.end());
    return reflectorPsnr(
        renderWithTruth(scene, "depthmap", size, settings, params, 0.0f, kMatchedSsaa));
  };
  const double one = psnr({});
  const double hit = psnr({{"srdm-rows", "2"}, {"srdm-second", "hit"}});
  const double blend = psnr({{"srdm-rows", "2"}, {"srdm-second", "interpolate"}});
  const double hit_blend = psnr({{"srdm-rows", "2"}, {"srdm-second", "hit-interpolate"}});
  std::printf(
      "n = 9, reflector PSNR: one row %.2f dB, hit %.2f, interpolate %.2f, "
      "hit-interpolate %.2f\n",
      one, hit, blend, hit_blend);
  // Measured under matched 2x2 sampling: one row 38.49 dB, hit 38.83, interpolate 39.06,
  // hit-interpolate 38.97.
  EXPECT_GT(hit, one);
  EXPECT_GT(blend, one);
  EXPECT_GT(hit_blend, one);
  EXPECT_NE(hit, blend);
  EXPECT_NE(hit, hit_blend);
  EXPECT_NE(blend, hit_blend);
}

TEST_F(DepthMapImages, GpuSrdmBuilderGivesTheCpuBuildersImage) {
  // The compute-shader builder works in place on the method's depth and SRDM arrays (texture
  // views of one layer and of n layers); its rows equal the CPU builder's, so the frames must
  // be the same bit for bit.
  const Scene scene = teapotSphereObjectsOnly();
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{240, 160};
  FrameRenderer renderer(scene, size);
  const View view(scene.camera(), size);
  auto frame = [&](const char* builder, int maps) {
    auto m = renderer.createMethod(
        "depthmap", {{"srdm-builder", builder}, {"depthmap-maps", std::to_string(maps)}}, settings);
    renderer.render(*m, view, 0.0f, settings);
    EXPECT_EQ(m->stats().at("srdm_builds"), 2.0 * maps) << builder;
    return renderer.read().color;
  };
  for (int maps : {1, 3}) {
    const Image cpu = frame("cpu", maps), gpu = frame("gpu", maps);
    ASSERT_EQ(cpu.size(), gpu.size());
    size_t differing = 0;
    for (size_t i = 0; i < cpu.pixelCount(); ++i)
      differing += cpu.pixels()[i] != gpu.pixels()[i] ? 1 : 0;
    EXPECT_EQ(differing, 0u) << maps << " maps per object";
  }
}

TEST_F(DepthMapImages, SelfMapsReflectAConcaveReflectorInItself) {
  // mirror-torus: the torus's inner surface sees itself. Without maps of itself a reflector
  // never reflects itself; with them, the pixels that change must move towards the ray tracer.
  const Scene scene = makeBuiltinScene("mirror-torus");
  FrameSettings settings;
  settings.order = 2;
  const ivec2 size{360, 256};
  RenderPair none = renderWithTruth(scene, "depthmap", size, settings);
  RenderPair self = renderWithTruth(scene, "depthmap", size, settings, {{"self-maps", "2"}});
  const std::vector<bool> changed = changedPixels(none.gpu, self.gpu);
  IdImage mask(size.x, size.y, 0u);
  size_t count = 0;
  for (size_t i = 0; i < changed.size(); ++i) {
    const bool on = changed[i] && none.cpu_ids.pixels()[i] != 0;
    mask.pixels()[i] = on ? 1u : 0u;
    count += on ? 1 : 0;
  }
  EXPECT_GT(count, 1000u) << "the torus must reflect itself on many pixels";
  const double before = psnrFromMse(meanSquaredError(none.gpu, none.cpu, &mask));
  const double after = psnrFromMse(meanSquaredError(self.gpu, self.cpu, &mask));
  std::printf("%zu pixels changed by 2 self maps: %.2f -> %.2f dB; reflector %.2f -> %.2f dB\n",
              count, before, after, reflectorPsnr(none), reflectorPsnr(self));
  // Measured: 1,723 pixels, 11.65 -> 14.19 dB there; reflector pixels 18.38 -> 18.79 dB.
  EXPECT_GT(after, before + 1.5);
  EXPECT_GT(reflectorPsnr(self), reflectorPsnr(none) + 0.2);
  EXPECT_TRUE(psnrAtLeast(self.gpu, self.cpu, floors::kDepthmapSelfMaps, &self.cpu_ids));
}

TEST_F(DepthMapImages, RigidMotionRebuildsNothingAndStaysCorrect) {
  Scene scene = teapotSphereObjectsOnly();
  const int teapot = instanceNamed(scene, "teapot");
  ASSERT_GE(teapot, 0);
  Instance& inst = scene.instances[size_t(teapot)];
  // t in [0, 1]: a translation; t in [1, 2]: a rotation about the vertical as well.
  Transform shifted = inst.transform, turned = inst.transform;
  shifted.translation += vec3(0.25f, 0.0f, 0.35f);
  turned.translation = shifted.translation;
  turned.rotation = glm::angleAxis(glm::radians(50.0f), vec3(0, 1, 0)) * inst.transform.rotation;
  inst.animation.keys = {{0.0f, inst.transform}, {1.0f, shifted}, {2.0f, turned}};

  const ivec2 size{240, 160};
  FrameRenderer renderer(scene, size);
  FrameSettings settings;
  settings.order = 1;
  auto m = renderer.createMethod("depthmap", {}, settings);
  auto stat = [&](const char* name) { return m->stats().at(name); };
  const View view(scene.camera(), size);
  renderer.render(*m, view, 0.0f, settings);
  EXPECT_EQ(stat("depth_maps"), 2.0);
  EXPECT_EQ(stat("srdm_builds"), 2.0);
  EXPECT_EQ(stat("depthmap_color_captures_last_update"), 2.0);
  renderer.render(*m, view, 1.0f, settings);
  EXPECT_EQ(stat("srdm_builds"), 2.0) << "a translation rebuilds no SRDM";
  EXPECT_EQ(stat("depthmap_depth_captures"), 2.0);
  EXPECT_EQ(stat("depthmap_color_captures_last_update"), 0.0)
      << "a translation leaves the light as the object sees it";
  renderer.render(*m, view, 2.0f, settings);
  EXPECT_EQ(stat("srdm_builds"), 2.0) << "a rotation rebuilds no SRDM";
  EXPECT_EQ(stat("depthmap_depth_captures"), 2.0);
  EXPECT_EQ(stat("depthmap_color_captures_last_update"), 1.0)
      << "the turned teapot sees the light from elsewhere: its colour alone is re-captured";

  // The moved teapot's reflection, through maps captured before it moved, against the ray
  // tracer at t = 2.
  const Image moved = displayed(renderer.read().color);
  RenderPair fresh = renderWithTruth(scene, "depthmap", size, settings, {}, 2.0f);
  // The maps are the same in the object's space: the frame is a fresh one's, but for float
  // rounding (the moved maps' matrices are products of other matrices); 33.1 dB to the truth.
  EXPECT_TRUE(
      imagesEqual(moved, fresh.gpu, kFloatRounding, &fresh.cpu_ids, "depthmap-moved-vs-fresh"));
  EXPECT_TRUE(psnrAtLeast(moved, fresh.cpu, floors::kDepthmapMovedVsTruth, &fresh.cpu_ids));
}

TEST(DepthMapCli, BadParametersExitWithTheAllowedRange) {
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"--srdm-n 0", "--srdm-n"},
      {"--srdm-m 1", "--srdm-m"},
      {"--depthmap-size 32 --srdm-m 64", "at most the depth map's size --depthmap-size"},
      {"--depthmap-size 8", "--depthmap-size"},
      {"--depthmap-size 5000", "--depthmap-size"},
      {"--depthmap-maps 7", "--depthmap-maps"},
      {"--srdm-simplify best", "--srdm-simplify"},
      {"--depthmap-search binary", "--depthmap-search"},
      {"--srdm-builder gpu --srdm-simplify fit", "--srdm-simplify greedy"},
  };
  for (const Case& c : cases) {
    const CliResult r =
        runMirage("render --scene teapot-sphere --method depthmap --size 32x32 -o " +
                  (testTempDir("depthmap-cli") / "bad.png").string() + " " + c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("allowed"), std::string::npos) << c.args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace mirage::test
