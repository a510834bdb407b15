// Image tests of the baseline methods against the ray tracer, with stated tolerances. On failure
// the actual/expected/diff images are written under build/<preset>/test-artifacts/.
#include <gtest/gtest.h>

#include "core/display.h"
#include "methods/frame.h"
#include "raytrace/tracer.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class BaselineImages : public GlTest {};

using Pair = RenderPair;

Pair renderBoth(const Scene& scene, const std::string& method, ivec2 size, FrameSettings settings) {
  return renderWithTruth(scene, method, size, settings);
}

TEST_F(BaselineImages, EnvmapInfiniteEqualsRaytraceWithoutLocalObjects) {
  Scene scene = mirrorSphereInSky();
  FrameSettings settings;
  settings.order = 1;
  settings.mip = false;  // the ray tracer samples level 0
  Pair p = renderBoth(scene, "envmap-infinite", {256, 192}, settings);
  // Same rasterised coverage as the traced coverage, but for a few silhouette pixels.
  IdImage both(p.cpu_ids.width(), p.cpu_ids.height());
  size_t differ = 0;
  for (size_t i = 0; i < both.pixelCount(); ++i) {
    differ += p.gpu_ids.data()[i] != p.cpu_ids.data()[i];
    both.data()[i] = p.gpu_ids.data()[i] == p.cpu_ids.data()[i] ? p.cpu_ids.data()[i] : 0u;
  }
  EXPECT_LT(differ, 40u);
  EXPECT_GT(countNonZero(both), 10000u);
  // Where both see the sphere, the reflections agree to within rounding, except at grazing
  // silhouette pixels where the reflected direction swings fastest (a handful).
  EXPECT_TRUE(mostPixelsWithin(p.gpu, p.cpu, 2.0f / 255.0f, 0.001, &both, "reflector-within"));
  EXPECT_TRUE(psnrAtLeast(p.gpu, p.cpu, floors::kEnvmapInfiniteReflector, &both));
  EXPECT_TRUE(psnrAtLeast(p.gpu, p.cpu, floors::kEnvmapInfiniteAll, nullptr));
}

TEST_F(BaselineImages, GpuShadingEqualsCpuShading) {
  // `none` on the GPU and the ray tracer at order 0 run the same shading code (shading/*.h):
  // they differ only where rasterisation and ray casting disagree on coverage at edges.
  Scene scene = makeBuiltinScene("sphere-over-checker");
  FrameSettings settings;
  settings.order = 0;
  Pair p = renderBoth(scene, "none", {360, 256}, settings);
  EXPECT_TRUE(mostPixelsWithin(p.gpu, p.cpu, 2.0f / 255.0f, 0.01, nullptr, "none-vs-order0"));
  EXPECT_TRUE(psnrAtLeast(p.gpu, p.cpu, floors::kNoneVsOrder0, nullptr));
}

TEST_F(BaselineImages, TexturesAreSampledAlikeOnGpuAndCpu) {
  // An 8x8 texture whose rows and columns all differ, magnified on a quad seen from above:
  // the GPU and the ray tracer must agree on its orientation (uv (0, 0) = bottom-left).
  Scene scene;
  scene.name = "textured-quad";
  TextureImage tex;
  tex.name = "gradient";
  tex.image = Image(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      tex.image(x, y) = vec4(float(x) / 7.0f, float(y) / 7.0f, 0.3f, 1.0f);
  scene.textures.push_back(tex);
  Material m = Material::diffuse("textured", vec3(1.0f));
  m.albedo_texture = 0;
  int mesh = addMesh(scene, procedural::quad(2.0f, 2.0f, 0.5f));
  int mat = addMaterial(scene, m);
  addInstance(scene, "quad", mesh, mat, {});
  finishScene(scene, {0.0f, 3.0f, 0.001f}, {0.0f, 0.0f, 0.0f}, 30.0f);
  FrameSettings settings;
  settings.order = 0;
  Pair p = renderBoth(scene, "none", {160, 160}, settings);
  EXPECT_TRUE(mostPixelsWithin(p.gpu, p.cpu, 3.0f / 255.0f, 0.01, nullptr, "texture"));
}

TEST_F(BaselineImages, EnvmapApproximatesRaytraceOnSphereOverChecker) {
  // A reflection probe ignores parallax: it must resemble the truth without equalling it.
  Scene scene = makeBuiltinScene("sphere-over-checker");
  FrameSettings settings;
  settings.order = 1;
  Pair p = renderBoth(scene, "envmap", {360, 256}, settings);
  // Measured: about 12.7 dB on reflector pixels at 360x256 (the checker is shifted by the
  // missing parallax); an orientation or capture error drops it below 9 dB.
  EXPECT_TRUE(psnrAtLeast(p.gpu, p.cpu, floors::kEnvmapSphereOverChecker, &p.cpu_ids));
  double psnr = psnrFromMse(meanSquaredError(p.gpu, p.cpu, &p.cpu_ids));
  EXPECT_LT(psnr, 40.0) << "a probe cannot reproduce the parallax of a nearby floor exactly";
}

TEST_F(BaselineImages, EnvmapBoxIsExactInAnEmptyBoxRoom) {
  // The room is the proxy box and the probe sits at the sphere's centre, inside it: every
  // reflected ray leaves the box at a wall point the probe saw along the corrected direction.
  Scene scene = mirrorSphereInRoom();
  FrameSettings settings;
  settings.order = 1;
  settings.mip = false;
  const ivec2 size{320, 240};
  Pair box = renderBoth(scene, "envmap-box", size, settings);
  Pair probe = renderBoth(scene, "envmap", size, settings);
  // Measured: 33.6 dB on reflector pixels (checker edges resampled through a 256^2 cube map)
  // against 16.6 dB for the uncorrected probe.
  EXPECT_TRUE(psnrAtLeast(box.gpu, box.cpu, floors::kEnvmapBoxInBoxRoom, &box.cpu_ids));
  EXPECT_TRUE(
      mostPixelsWithin(box.gpu, box.cpu, 8.0f / 255.0f, 0.05, &box.cpu_ids, "envmap-box-within"));
  double corrected = psnrFromMse(meanSquaredError(box.gpu, box.cpu, &box.cpu_ids));
  double plain = psnrFromMse(meanSquaredError(probe.gpu, probe.cpu, &probe.cpu_ids));
  EXPECT_GT(corrected, plain + 10.0) << "the box proxy must remove the probe's parallax error";
}

TEST_F(BaselineImages, HigherOrderChangesOnlyReflectorPixels) {
  Scene scene = makeBuiltinScene("two-mirrors");
  FrameSettings one, three;
  one.order = 1;
  three.order = 3;
  ivec2 size{240, 160};
  FrameRenderer renderer(scene, size);
  View view(scene.camera(), size);
  for (const char* method : {"envmap", "envmap-box", "billboard", "raytrace"}) {
    auto a = renderer.createMethod(method, {}, one);
    renderer.render(*a, view, 0.0f, one);
    RenderedFrame fa = renderer.read();
    auto b = renderer.createMethod(method, {}, three);
    renderer.render(*b, view, 0.0f, three);
    RenderedFrame fb = renderer.read();
    size_t changed_reflector = 0, changed_other = 0;
    const std::vector<bool> changed = changedPixels(fa.color, fb.color);
    for (size_t i = 0; i < changed.size(); ++i)
      if (changed[i]) (fa.ids.data()[i] != 0 ? changed_reflector : changed_other)++;
    EXPECT_EQ(changed_other, 0u) << method;
    EXPECT_GT(changed_reflector, 100u)
        << method << ": mirror-in-mirror paths must appear at order 3";
  }
}

TEST_F(BaselineImages, EnvmapRecapturesOnlyWhenTheSceneChanges) {
  Scene scene = makeBuiltinScene("sphere-over-checker");
  // Animate one box so that time changes the scene.
  Instance& box = scene.instances[1];
  box.animation.keys = {{0.0f, box.transform}, {1.0f, box.transform}};
  box.animation.keys[1].transform.translation.x += 1.0f;
  ivec2 size{64, 48};
  FrameRenderer renderer(scene, size);
  FrameSettings settings;
  auto m = renderer.createMethod("envmap", {}, settings);
  CameraDesc cam = scene.camera();
  renderer.render(*m, View(cam, size), 0.0f, settings);
  double first = m->stats().at("cube_captures");
  EXPECT_EQ(first, 1.0);   // one reflector, one pass
  cam.position.x += 2.0f;  // a view change alone
  renderer.render(*m, View(cam, size), 0.0f, settings);
  renderer.render(*m, View(cam, size), 0.0f, settings);
  EXPECT_EQ(m->stats().at("cube_captures"), first);
  renderer.render(*m, View(cam, size), 0.5f, settings);  // the box moved
  EXPECT_EQ(m->stats().at("cube_captures"), first + 1.0);
}

}  // namespace
}  // namespace mirage::test
