// Captured cube faces have the orientation GL's sampler expects: capturing the environment
// through the background pass reproduces the environment's own texels.
#include <gtest/gtest.h>

#include <algorithm>

#include "raytrace/tracer.h"
#include "render/cube_capture.h"
#include "render/gpu_scene.h"
#include "render/scene_passes.h"
#include "scene/builtin_scenes.h"
#include "shading/cubemap.h"
#include "shading/shading.h"
#include "support/gl_test.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class CubeCaptureTest : public GlTest {};

// Captures `scene` from `centre` into a size^3 cube: the environment, and the diffuse objects
// when `diffuse` (reflectors are never drawn). Returns the six faces' level-0 texels, face-major.
std::vector<vec4> captureCube(const Scene& scene, const EnvironmentMap& env, const vec3& centre,
                              int size, bool diffuse, GLenum format = GL_RGBA32F) {
  GpuScene gpu(scene, env);
  ScenePasses passes(gpu);
  gpu::Texture cube = gpu::Texture::createCube(format, size);
  CubeCapture capture(size);
  capture.capture(cube, 0, centre, 0.01f, 1000.0f, [&](const View& v) {
    passes.begin(v, FrameSettings{});
    passes.drawBackground();
    if (diffuse) passes.drawDiffuse();
  });
  std::vector<vec4> pixels(size_t(size * size * 6));
  glGetTextureImage(cube.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(vec4)),
                    pixels.data());
  return pixels;
}

TEST_F(CubeCaptureTest, BackgroundCaptureReproducesTheEnvironment) {
  Scene scene = mirrorSphereInSky();
  EnvironmentMap env = EnvironmentMap::sky(scene.light, 32);
  const int size = 32;
  const std::vector<vec4> pixels = captureCube(scene, env, vec3(0.0f), size, false);
  double worst = 0.0, sum = 0.0;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        vec3 got = vec3(pixels[size_t((f * size + y) * size + x)]);
        vec3 want = env.texel(f, x, y);
        double error = glm::length(got - want) / (1.0f + glm::length(want));
        worst = std::max(worst, error);
        sum += error;
      }
  // Texel centres sample texel centres: equal up to float rounding of the ray directions (which
  // matters only on the steep sun). A mis-oriented face is off by tens of percent.
  EXPECT_LT(worst, 5e-3) << "cube faces are mis-oriented";
  EXPECT_LT(sum / double(6 * size * size), 5e-4);
}

// A reflection probe is a camera at a point: a capture of the diffuse scene from the mirror
// sphere's centre must show what rays traced from that centre see. This checks the capture's
// projection, face orientation and depth test against the ground truth, on real geometry.
TEST_F(CubeCaptureTest, DiffuseCaptureMatchesRaysTracedFromTheProbeCentre) {
  Scene scene = makeBuiltinScene("sphere-over-checker");
  const std::vector<int> reflectors = scene.reflectorInstances();
  ASSERT_EQ(reflectors.size(), 1u);
  const vec3 centre =
      vec3(scene.instances[size_t(reflectors[0])].matrixAt(0.0f) * vec4(0, 0, 0, 1));
  EnvironmentMap env = EnvironmentMap::sky(scene.light, 64);
  const int size = 64;
  // Background and diffuse objects: the sphere itself is not drawn.
  const std::vector<vec4> pixels = captureCube(scene, env, centre, size, true);

  // The same scene without the sphere, traced from its centre through every texel centre.
  Scene diffuse_only = scene;
  diffuse_only.instances.erase(diffuse_only.instances.begin() + reflectors[0]);
  RayTracer tracer(diffuse_only, env);
  tracer.prepare(0.0f);
  int floor_texels = 0, off = 0;
  double sum = 0.0;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        vec2 st((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
        vec3 dir = glm::normalize(shading::cube_direction(f, st));
        uint64_t reflected = 0;
        TracedRadiance want = tracer.trace(Ray{centre, dir}, 0, reflected);
        vec3 got = vec3(pixels[size_t((f * size + y) * size + x)]);
        double error = glm::length(got - want.radiance) / (0.05f + glm::length(want.radiance));
        sum += error;
        if (error > 0.05) ++off;
        if (dir.y < -0.2f) ++floor_texels;
      }
  const int texels = 6 * size * size;
  ASSERT_GT(floor_texels, texels / 5) << "the probe must see the checker floor";
  // Texels on a checker edge may land on either side in the rasteriser and the tracer; a
  // mis-oriented or mis-projected face puts whole cells on the wrong side (tens of percent).
  EXPECT_LT(double(off) / texels, 0.02) << off << " of " << texels << " texels differ by > 5%";
  EXPECT_LT(sum / texels, 0.01);
}

TEST_F(CubeCaptureTest, AHalfFloatProbeTellsTheSkyByItsDistance) {
  // Probes are half floats (render/probe_array.h), which cannot hold MISS_DISTANCE: a driver
  // stores the sky's distance as the largest half (llvmpipe) or as +inf. Either must read as
  // the sky (PROBE_SKY_DISTANCE), and what the probe sees (a diffuse object here) must not.
  Scene scene = spheresOverFloor(/*floor_only=*/true);
  EnvironmentMap env = EnvironmentMap::sky(scene.light, 16);
  const std::vector<vec4> pixels = captureCube(scene, env, vec3(0.0f, 1.0f, 0.0f), 16, true,
                                               GL_RGBA16F);
  int sky = 0, floor = 0;
  for (const vec4& p : pixels) {
    if (p.w >= shading::PROBE_SKY_DISTANCE) {
      ++sky;
    } else {
      ++floor;
      EXPECT_LT(p.w, 20.0f);  // the 8 x 8 floor, 1 below the centre
    }
  }
  EXPECT_GE(sky, 16 * 16 * 3);    // the upper faces' texels and the side faces' upper halves
  EXPECT_GE(floor, 16 * 16);      // the lower face at least
}

}  // namespace
}  // namespace mirage::test
