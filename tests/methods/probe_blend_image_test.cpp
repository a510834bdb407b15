// A scene's own probes (scene/probes.h) blended by position in `envmap` and `envmap-box`
// (render/shaders/probe_lookup.glsl, PROBE_BLEND): across the blend region of two probes, every
// mirror pixel is the two single-probe frames mixed by the shares that shading/probe_blend.h
// gives at its shaded point. So the reflection has no step there (the shares are continuous),
// and the blend is the cited engine's, checked pixel by pixel against the very code.
#include <gtest/gtest.h>

#include <algorithm>

#include "methods/frame.h"
#include "shading/probe_blend.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class ProbeBlendImages : public GlTest {};

constexpr float kMirrorZ = -2.95f;

// A checkered corridor 16 x 3 x 6 with a 12 x 2 mirror along its back wall, a red ball at the
// west end, a blue ball at the east end and a green box between, seen from the front.
Scene corridor() {
  Scene s;
  s.name = "probe-corridor";
  const int room = addMesh(s, procedural::box({8.0f, 1.5f, 3.0f}, true));
  addInstance(s, "room", room,
              addMaterial(s, Material::checker("walls", kCheckerLight, {0.3f, 0.4f, 0.6f}, 1.0f)),
              placeAt({0.0f, 1.5f, 0.0f}));
  const int mirror = addMesh(s, procedural::quad(12.0f, 2.0f));
  addInstance(s, "mirror", mirror, addMaterial(s, Material::mirror("mirror")),
              placeAt({0.0f, 1.5f, kMirrorZ}, vec3(1.0f),
                      glm::angleAxis(glm::radians(90.0f), vec3(1.0f, 0.0f, 0.0f))));
  const int ball = addMesh(s, procedural::sphere(0.5f, 48, 24));
  addInstance(s, "red-ball", ball, addMaterial(s, Material::diffuse("red", {0.85f, 0.2f, 0.15f})),
              placeAt({-4.0f, 0.6f, 0.5f}));
  addInstance(s, "blue-ball", ball,
              addMaterial(s, Material::diffuse("blue", {0.2f, 0.35f, 0.85f})),
              placeAt({4.0f, 0.6f, 0.5f}));
  addBox(s, "green-box", {0.0f, 0.5f, 1.0f}, vec3(0.5f), {0.2f, 0.75f, 0.3f}, 20.0f);
  finishScene(s, vec3{0.0f, 1.6f, 2.8f}, vec3{0.0f, 1.5f, -3.0f}, 60.0f);
  return s;
}

// A probe at `position` whose influence is [lo, hi] with `blend`, its proxy the corridor.
ReflectionProbe probeAt(const std::string& name, vec3 position, vec3 lo, vec3 hi, float blend) {
  ReflectionProbe p;
  p.name = name;
  p.position = position;
  p.influence.box = Bounds3{lo, hi};
  p.blend_distance = blend;
  p.proxy.box = Bounds3{{-8.0f, 0.0f, -3.0f}, {8.0f, 3.0f, 3.0f}};
  return p;
}

const vec3 kWest(-4.0f, 1.5f, 1.5f), kEast(3.5f, 1.5f, 1.0f);
constexpr float kBlend = 1.0f;

ReflectionProbe westProbe() {
  return probeAt("west", kWest, {-9.0f, -1.0f, -4.0f}, {1.0f, 4.0f, 4.0f}, kBlend);
}
ReflectionProbe eastProbe() {
  return probeAt("east", kEast, {-1.0f, -1.0f, -4.0f}, {9.0f, 4.0f, 4.0f}, kBlend);
}
// The probe at `position` alone, influencing everything fully.
ReflectionProbe aloneAt(const std::string& name, vec3 position) {
  return probeAt(name, position, vec3(-50.0f), vec3(50.0f), 0.0f);
}

RenderedFrame render(Scene scene, std::vector<ReflectionProbe> probes, const std::string& method) {
  scene.probes = std::move(probes);
  const ivec2 size{240, 160};
  FrameRenderer renderer(scene, size);
  FrameSettings settings;
  settings.order = 1;
  settings.mip = false;
  auto m = renderer.createMethod(method, {}, settings);
  renderer.render(*m, View(scene.camera(), size), 0.0f, settings);
  EXPECT_EQ(m->stats().at("probes"), double(scene.probes.size()));
  return renderer.read();
}

void expectTheBlendOfTheSingleProbes(const std::string& method) {
  const Scene scene = corridor();
  const RenderedFrame blended = render(scene, {westProbe(), eastProbe()}, method);
  const RenderedFrame west = render(scene, {aloneAt("west", kWest)}, method);
  const RenderedFrame east = render(scene, {aloneAt("east", kEast)}, method);
  const View view(scene.camera(), blended.color.size());
  const ReflectionProbe w = westProbe(), e = eastProbe();
  ASSERT_EQ(probeBlendOrder({w, e}), (std::vector<int>{0, 1}));  // equal volumes: scene order

  Image expected = blended.color;
  IdImage mask(blended.ids.width(), blended.ids.height());
  const uint32_t mirror_id = 1;
  int in_blend = 0;
  double apart = 0.0;
  for (int y = 1; y + 1 < mask.height(); ++y)
    for (int x = 1; x + 1 < mask.width(); ++x) {
      // Mirror pixels away from its edges (all four neighbours on it too).
      if (blended.ids(x, y) != mirror_id || blended.ids(x - 1, y) != mirror_id ||
          blended.ids(x + 1, y) != mirror_id || blended.ids(x, y - 1) != mirror_id ||
          blended.ids(x, y + 1) != mirror_id)
        continue;
      const Ray ray = view.primaryRay(float(x) + 0.5f, float(y) + 0.5f);
      const vec3 p = ray.origin + (kMirrorZ - ray.origin.z) / ray.direction.z * ray.direction;
      const float sw = shading::probe_blend_share(
          shading::probe_box_weight(p, w.influence.box.lo, w.influence.box.hi, kBlend), 0.0f);
      const float se = shading::probe_blend_share(
          shading::probe_box_weight(p, e.influence.box.lo, e.influence.box.hi, kBlend), sw);
      ASSERT_NEAR(sw + se, 1.0f, 1e-5f) << "the probes cover the mirror: no sky share";
      const vec4 mix = sw * west.color(x, y) + se * east.color(x, y);
      expected(x, y) = vec4(vec3(mix), blended.color(x, y).w);
      mask(x, y) = mirror_id;
      if (sw > 0.05f && sw < 0.95f) {
        ++in_blend;
        apart += glm::length(vec3(west.color(x, y) - east.color(x, y)));
      }
    }
  // The walk crosses the blend region on many pixels, and there the two probes see differently:
  // a lookup that took one probe only, or stepped, would fail.
  ASSERT_GT(in_blend, 800);
  EXPECT_GT(apart / in_blend, 0.02);
  EXPECT_TRUE(imagesEqual(blended.color, expected, 2e-4f, &mask, method + "-blend"));
}

TEST_F(ProbeBlendImages, EnvmapMixesTwoProbesByTheSharesAtEachPoint) {
  expectTheBlendOfTheSingleProbes("envmap");
}

TEST_F(ProbeBlendImages, EnvmapBoxMixesTwoProbesByTheSharesAtEachPoint) {
  expectTheBlendOfTheSingleProbes("envmap-box");
}

// ssr's pass is built for its fallback's lookup of the scene's probes (ProbeLookup::kindFor): it
// compiles, and where the screen has nothing its pixels are envmap-box's blend.
TEST_F(ProbeBlendImages, SsrLooksUpTheScenesProbesWhereTheScreenHasNothing) {
  const Scene scene = corridor();
  const RenderedFrame ssr = render(scene, {westProbe(), eastProbe()}, "ssr");
  const RenderedFrame box = render(scene, {westProbe(), eastProbe()}, "envmap-box");
  // The mirror faces the camera: most reflected rays leave the screen, so most mirror pixels are
  // the fallback's alone.
  size_t mirror = 0, same = 0;
  for (int y = 0; y < ssr.ids.height(); ++y)
    for (int x = 0; x < ssr.ids.width(); ++x) {
      if (ssr.ids(x, y) != 1u) continue;
      ++mirror;
      same += glm::length(vec3(ssr.color(x, y) - box.color(x, y))) < 1e-4f;
    }
  ASSERT_GT(mirror, 10000u);
  EXPECT_GT(double(same), 0.5 * double(mirror));
}

}  // namespace
}  // namespace mirage::test
