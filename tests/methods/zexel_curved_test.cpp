// Method `zexel`'s curved reflectors: the inverse warp (zexel_inverse_shared.h, the shader's
// search) over cube maps of distances ray-cast analytically from a known scene, against the
// analytic intersection of each ray; and on the GPU the method's frame against the ray tracer
// and `envmap` on a curved-mirror scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "methods/frame.h"
#include "methods/zexel/zexel_cube_map.h"
#include "scene/builtin_scenes.h"
#include "shading/shading.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

constexpr float kNone = std::numeric_limits<float>::infinity();

// The oracle's scene: a square floor (y = 0, half-size 6) and five spheres around the reference
// centre (0, 1, 0), at different distances, one in front of another as seen from the centre
// (silhouettes over a surface behind), none within 0.9 of the centre (the reflector's room).
struct AnalyticScene {
  vec4 spheres[5] = {{1.8f, 0.6f, 0.3f, 0.5f},
                     {-1.2f, 1.3f, -1.5f, 0.6f},
                     {0.3f, 0.4f, 2.0f, 0.35f},
                     {0.0f, 2.8f, -0.5f, 0.4f},
                     {-2.6f, 1.9f, -3.2f, 0.9f}};  // behind the second, seen around it

  // The first hit's distance along the unit ray, or kNone.
  float cast(const vec3& o, const vec3& d) const {
    float best = kNone;
    if (d.y < 0.0f) {
      const float t = -o.y / d.y;
      const vec3 x = o + t * d;
      if (t > 0.0f && std::abs(x.x) <= 6.0f && std::abs(x.z) <= 6.0f) best = t;
    }
    for (const vec4& s : spheres) {
      const vec3 oc = o - vec3(s);
      const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.w * s.w, disc = b * b - c;
      if (disc < 0.0f) continue;
      const float t = -b - std::sqrt(disc);
      if (t > 0.0f && t < best) best = t;
    }
    return best;
  }
};

// The distances from `centre` through every texel centre (the sky: MISS_DISTANCE, as the
// captures store it).
ZexelCubeMap rayCastMap(const AnalyticScene& scene, const vec3& centre, int size) {
  ZexelCubeMap map;
  map.size = size;
  map.centre = centre;
  for (int f = 0; f < 6; ++f) {
    map.faces[size_t(f)].resize(size_t(size) * size_t(size));
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float t = scene.cast(centre, map.texelDirection(f, x, y));
        map.faces[size_t(f)][size_t(y) * size_t(size) + size_t(x)] =
            vec4(0.0f, 0.0f, 0.0f, t == kNone ? shading::MISS_DISTANCE : t);
      }
  }
  map.buildBounds();
  return map;
}

struct OracleResult {
  int seen = 0, seen_within = 0;     // hits the map saw; those found within the tolerance
  int seen_to_sky = 0;               // seen hits the search missed
  int hidden = 0;                    // hits the map did not see (occluded from the centre)
  int hidden_flagged = 0;            // those the search flags as exposed
  int misses = 0, misses_agree = 0;  // rays to the sky; those the search sends to the sky
  int false_hits = 0;                // hits claimed for hidden or sky rays
  double median_texels = 0.0, p95_texels = 0.0;  // error over the seen hits, in texels
  double samples = 0.0;                          // mean map reads per ray
};

// Random rays from a sphere of radius 0.5 around the centre (a reflector's surface), leaving it,
// searched in a map of face `size`; the error of a seen hit in units of the texel's size at the
// hit, π / (2 size) · |x − c|.
OracleResult runOracle(int size, float step_texels, float max_slope, float tolerance_texels,
                       float radius = 0.5f, bool bounds = true) {
  const AnalyticScene scene;
  const vec3 centre(0.0f, 1.0f, 0.0f);
  const ZexelCubeMap map = rayCastMap(scene, centre, size);
  ZexelInverseSettings settings = zexelInverseSettings(size, step_texels, bounds);
  settings.max_slope = max_slope;
  const float texel_angle = 0.5f * glm::pi<float>() / float(size);
  std::mt19937 rng(11);
  std::normal_distribution<float> gauss;
  auto unit = [&] { return glm::normalize(vec3(gauss(rng), gauss(rng), gauss(rng))); };
  OracleResult r;
  std::vector<double> errors;
  const int rays = 20000;
  long samples = 0;
  for (int i = 0; i < rays; ++i) {
    const vec3 normal = unit();
    const vec3 origin = centre + radius * normal;
    vec3 dir = unit();
    if (glm::dot(dir, normal) < 0.0f) dir = -dir;
    const ZexelInverseHit hit = zexelInverseWarp(map, origin, dir, settings);
    samples += hit.samples;
    const float t = scene.cast(origin, dir);
    if (t == kNone) {
      ++r.misses;
      r.misses_agree += hit.t < 0.0f ? 1 : 0;
      r.false_hits += hit.t < 0.0f ? 0 : 1;
      continue;
    }
    const vec3 x = origin + t * dir;
    const float from_centre = glm::length(x - centre);
    if (scene.cast(centre, (x - centre) / from_centre) < from_centre * (1.0f - 1e-4f)) {
      ++r.hidden;
      r.hidden_flagged += hit.status == kZexelInverseExposed ? 1 : 0;
      r.false_hits += hit.t < 0.0f ? 0 : 1;
      continue;
    }
    ++r.seen;
    const double error = hit.t < 0.0f ? 1e9
                                      : double(glm::length(origin + hit.t * dir - x)) /
                                            double(texel_angle * from_centre);
    errors.push_back(error);
    r.seen_within += error <= tolerance_texels ? 1 : 0;
    r.seen_to_sky += hit.t < 0.0f ? 1 : 0;
  }
  std::sort(errors.begin(), errors.end());
  r.median_texels = errors[errors.size() / 2];
  r.p95_texels = errors[errors.size() * 95 / 100];
  r.samples = double(samples) / rays;
  return r;
}

void print(const char* what, int size, const OracleResult& r) {
  std::printf(
      "%s, face %d: %d seen hits, %.2f %% within tolerance (median %.3f, 95th percentile %.2f "
      "texels); %d hidden, %d of them flagged exposed; %d sky rays, %.2f %% to the sky; %.0f map "
      "reads "
      "per ray; %d false hits\n",
      what, size, r.seen, 100.0 * r.seen_within / r.seen, r.median_texels, r.p95_texels, r.hidden,
      r.hidden_flagged, r.misses, 100.0 * r.misses_agree / r.misses, r.samples, r.false_hits);
}

// The search finds the analytic hit of the rays whose hit the map saw, to within two texels'
// size at the hit, for almost all of them; sky rays stay in the sky. Measured: 97.9 % (face
// 128) and 99.3 % (512) within two texels, median 0.005 and 0.001 texels; the others are hits
// the map sees within about a texel of a silhouette (the ray is behind the surface for less than
// a step) or rejected as too steep.
TEST(ZexelInverseWarp, FindsTheAnalyticHitOfRaysThatTheMapSaw) {
  for (int size : {128, 512}) {
    const OracleResult r = runOracle(size, 1.0f, zexelInverseSettings(size, 1.0f).max_slope, 2.0f);
    print("one-texel steps", size, r);
    EXPECT_GT(r.seen, 5000);
    EXPECT_GT(double(r.seen_within) / r.seen, size == 128 ? 0.96 : 0.985);
    EXPECT_LT(r.median_texels, 0.25);
    EXPECT_GT(double(r.misses_agree) / r.misses, 0.97);
  }
}

// Without the discontinuity test a ray that passes behind a silhouette stops on the
// interpolated ramp between the two surfaces: a false hit where the ray went on to something the
// map did not see, or to the sky (from origins 0.9 from the centre: more parallax, more rays
// behind silhouettes). The test costs a few true hits seen within about a texel of a
// silhouette (a steep stored slope).
TEST(ZexelInverseWarp, RejectingDiscontinuitiesAvoidsFalseHits) {
  const OracleResult with =
      runOracle(256, 1.0f, zexelInverseSettings(256, 1.0f).max_slope, 2.0f, 0.9f);
  const OracleResult without = runOracle(256, 1.0f, 1e30f, 2.0f, 0.9f);
  print("slope test", 256, with);
  print("no slope test", 256, without);
  // Measured: 10 false hits with the test, 148 without; 9,277 and 9,289 of 9,388 seen hits
  // within two texels.
  EXPECT_LT(2 * with.false_hits, without.false_hits);
  EXPECT_GT(with.seen_within + 50, without.seen_within);
}

// Coarser steps (a fixed budget) may step over thin parts of the epipolar line; the refinement
// keeps the hits they find as precise.
TEST(ZexelInverseWarp, CoarseStepsStillRefineToTheHit) {
  const OracleResult r = runOracle(256, 4.0f, zexelInverseSettings(256, 4.0f).max_slope, 2.0f);
  print("four-texel steps", 256, r);
  EXPECT_GT(double(r.seen_within) / r.seen, 0.9);
  EXPECT_LT(r.median_texels, 0.25);
}

// The bounds cross empty stretches of the epipolar line, and the search ends where the ray passes
// the map's farthest distance, without changing what it finds: every ray's hit as the linear
// search's to the end (to rounding), in far fewer reads.
TEST(ZexelInverseWarp, BoundsSkipEmptyStretchesWithoutChangingAnyHit) {
  const AnalyticScene scene;
  const vec3 centre(0.0f, 1.0f, 0.0f);
  for (int size : {64, 256}) {
    for (float step_texels : {1.0f, 3.0f}) {
      const ZexelCubeMap map = rayCastMap(scene, centre, size);
      ZexelCubeMap unbounded = map;  // nor left when the ray passes the farthest distance
      unbounded.far = shading::MISS_DISTANCE;
      const ZexelInverseSettings linear = zexelInverseSettings(size, step_texels, false);
      const ZexelInverseSettings bounded = zexelInverseSettings(size, step_texels, true);
      ASSERT_GT(bounded.top_level, 0);
      ASSERT_EQ(linear.top_level, 0);
      std::mt19937 rng(5);
      std::normal_distribution<float> gauss;
      auto unit = [&] { return glm::normalize(vec3(gauss(rng), gauss(rng), gauss(rng))); };
      long reads_linear = 0, reads_bounded = 0;
      int differ = 0;
      const int rays = 20000;
      for (int i = 0; i < rays; ++i) {
        const vec3 normal = unit();
        vec3 dir = unit();
        if (glm::dot(dir, normal) < 0.0f) dir = -dir;
        const vec3 origin = centre + (0.4f + 0.5f * float(i % 2)) * normal;
        const ZexelInverseHit a = zexelInverseWarp(unbounded, origin, dir, linear);
        const ZexelInverseHit b = zexelInverseWarp(map, origin, dir, bounded);
        reads_linear += a.samples;
        reads_bounded += b.samples;
        // The same to rounding: the march turns by other angles after a stretch crossed.
        const bool same = a.status == b.status && std::abs(a.t - b.t) <= 1e-5f * std::abs(a.t) &&
                          glm::length(a.direction - b.direction) <= 1e-5f;
        if (!same) {
          if (differ < 5)
            ADD_FAILURE() << "face " << size << ", step " << step_texels << ", ray " << i << ": t "
                          << a.t << " linear, " << b.t << " with bounds; status " << a.status
                          << ", " << b.status;
          ++differ;
        }
      }
      std::printf("face %d, %.0f-texel steps: %.1f reads a ray linear, %.1f with bounds\n", size,
                  double(step_texels), double(reads_linear) / rays, double(reads_bounded) / rays);
      EXPECT_EQ(differ, 0);
      EXPECT_LE(reads_bounded, reads_linear + reads_linear / 100);
      // Measured: 143.7 reads a ray linear, 35.8 with bounds (face 256, one-texel steps); 39.1
      // and 24.1 at face 64; none skipped at face 64 with three-texel steps (no level's stretch
      // holds two steps: the search is the linear one).
      if (size == 256 && step_texels == 1.0f) {
        EXPECT_LT(3 * reads_bounded, reads_linear);
      }
    }
  }
}

// A ray from the centre itself is the map's own line of sight: its hit is the stored distance.
TEST(ZexelInverseWarp, RayFromTheCentreHitsTheStoredDistance) {
  const AnalyticScene scene;
  const vec3 centre(0.0f, 1.0f, 0.0f);
  const ZexelCubeMap map = rayCastMap(scene, centre, 128);
  for (vec3 d : {vec3(0.0f, -1.0f, 0.0f), glm::normalize(vec3(1.8f, -0.4f, 0.3f))}) {
    const ZexelInverseHit hit = zexelInverseWarp(map, centre, d, zexelInverseSettings(128, 1.0f));
    EXPECT_NEAR(hit.t, map.sample(d).w, 1e-3f * map.sample(d).w);
  }
}

class ZexelCurvedImages : public GlTest {};

// teapot-sphere: a mirror sphere with a teapot and a torus close beside it, whose reflections
// move with the point on the sphere (parallax) where a direction-only lookup cannot.
TEST_F(ZexelCurvedImages, CurvedMirrorShowsParallaxBetterThanEnvironmentMaps) {
  const Scene scene = makeBuiltinScene("teapot-sphere");
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{320, 240};
  const RenderPair zexel = renderWithTruth(scene, "zexel", size, settings, {}, 0.0f, kMatchedSsaa);
  const RenderPair envmap =
      renderWithTruth(scene, "envmap", size, settings, {}, 0.0f, kMatchedSsaa);
  const RenderPair base = renderWithTruth(scene, "zexel", size, settings,
                                          {{"zexel-curved", "base"}}, 0.0f, kMatchedSsaa);
  std::printf("teapot-sphere reflector PSNR: zexel %.2f dB, envmap %.2f dB, zexel base %.2f dB\n",
              reflectorPsnr(zexel), reflectorPsnr(envmap), reflectorPsnr(base));
  // Measured under matched 2x2 sampling: 25.4 dB against 13.0 (base colour 5.4; 20.8 against
  // 12.9 at one sample a pixel).
  EXPECT_GT(reflectorPsnr(zexel), reflectorPsnr(envmap) + 10.0);
  EXPECT_TRUE(meetsFloor(reflectorPsnr(zexel), floors::kZexelCurved));
  // Every pixel of the sphere is shaded by the inverse warp: the base-colour pass drawn after it
  // fails the depth test there (one invariant vertex shader), so none shows the base frame's value.
  const std::vector<bool> changed = changedPixels(base.gpu, zexel.gpu);
  size_t sphere = 0, unchanged = 0;
  for (size_t i = 0; i < changed.size(); ++i)
    if (zexel.gpu_ids.pixels()[i] != 0) {
      ++sphere;
      unchanged += changed[i] ? 0 : 1;
    }
  std::printf("%zu of %zu sphere pixels as in the base frame\n", unchanged, sphere);
  EXPECT_GT(sphere, 5000u);
  EXPECT_LT(unchanged, sphere / 1000) << unchanged << " of " << sphere << " sphere pixels";
}

// On the GPU the bounds and the early end change no pixel of the frame, and the searches read the
// maps far fewer times (zexel_curved_reads_per_ray): spheres9's nine spheres above a floor and
// among objects, and teapot-sphere's sphere with the teapot and torus close beside it.
TEST_F(ZexelCurvedImages, BoundsChangeNoPixelAndSaveReads) {
  for (const char* name : {"spheres9", "teapot-sphere"}) {
    const Scene scene = makeBuiltinScene(name);
    const ivec2 size{240, 170};
    FrameRenderer renderer(scene, size);
    FrameSettings settings;
    settings.order = 1;
    const View view(scene.camera(), size);
    RenderedFrame frames[2];
    double reads[2] = {0.0, 0.0};
    for (int on = 0; on < 2; ++on) {
      auto m =
          renderer.createMethod("zexel", {{"zexel-curved-bounds", on ? "on" : "off"}}, settings);
      renderer.render(*m, view, 0.0f, settings);
      frames[on] = renderer.read();
      reads[on] = m->stats().at("zexel_curved_reads_per_ray");
      EXPECT_GT(m->stats().at("zexel_curved_pixels"), 1000.0) << name;
    }
    std::printf("%s: %.1f reads a ray without the bounds, %.1f with\n", name, reads[0], reads[1]);
    // Measured: 105.8 and 31.5 on spheres9 at 720x512 (llvmpipe).
    EXPECT_LT(2.0 * reads[1], reads[0]) << name;
    EXPECT_TRUE(mostPixelsWithin(displayed(frames[1].color), displayed(frames[0].color), 2.0f / 255,
                                 1e-3, nullptr, std::string("bounds-") + name));
  }
}

// The cube maps are captured once and again only when the scene changes, not on camera moves;
// `base` captures none.
TEST_F(ZexelCurvedImages, CapturesOnlyWhenTheSceneChanges) {
  Scene scene = makeBuiltinScene("teapot-sphere");
  const ivec2 size{96, 72};
  FrameRenderer renderer(scene, size);
  FrameSettings settings;
  settings.order = 1;
  auto m = renderer.createMethod("zexel", {}, settings);
  auto stat = [&](const char* name) { return m->stats().at(name); };
  CameraDesc moved = scene.camera();
  moved.position += vec3(0.4f, 0.1f, -0.3f);
  renderer.render(*m, View(scene.camera(), size), 0.0f, settings);
  renderer.render(*m, View(moved, size), 0.0f, settings);
  EXPECT_EQ(stat("zexel_curved_reflectors"), 1.0);
  EXPECT_EQ(stat("zexel_cube_captures"), 1.0);
  EXPECT_EQ(stat("reflectors_not_planar"), 1.0);
  auto base = renderer.createMethod("zexel", {{"zexel-curved", "base"}}, settings);
  renderer.render(*base, View(scene.camera(), size), 0.0f, settings);
  EXPECT_EQ(base->stats().at("zexel_curved_reflectors"), 0.0);
  EXPECT_EQ(base->stats().at("zexel_cube_captures"), 0.0);
}

TEST(ZexelCurvedCli, BadParametersExitWithTheAllowedRange) {
  for (const char* bad : {"--zexel-cube-size 8", "--zexel-cube-size 4096", "--zexel-curved none",
                          "--zexel-curved-step 0.1"}) {
    const CliResult r =
        runMirage(std::string("render --scene teapot-sphere --method zexel --size 32x32 -o ") +
                  (testTempDir("zexel-curved-cli") / "bad.png").string() + " " + bad);
    EXPECT_EQ(r.code, 2) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("allowed"), std::string::npos) << bad << "\n" << r.output;
  }
}

}  // namespace
}  // namespace mirage::test
