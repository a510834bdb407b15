// Captured cube faces have the orientation GL's sampler expects: capturing the environment
// through the background pass reproduces the environment's own texels.
#include <gtest/gtest.h>

#include "render/cube_capture.h"
#include "render/gpu_scene.h"
#include "render/scene_passes.h"
#include "support/gl_test.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class CubeCaptureTest : public GlTest {};

TEST_F(CubeCaptureTest, BackgroundCaptureReproducesTheEnvironment) {
  Scene scene = mirrorSphereInSky();
  EnvironmentMap env = EnvironmentMap::sky(scene.light, 32);
  GpuScene gpu(scene, env);
  ScenePasses passes(gpu);
  const int size = 32;
  gpu::Texture cube = gpu::Texture::createCube(GL_RGBA32F, size);
  CubeCapture capture(size);
  capture.capture(cube, 0, vec3(0.0f), 0.01f, 100.0f, [&](const View& v) {
    passes.begin(v, FrameSettings{});
    passes.drawBackground();
  });
  std::vector<vec4> pixels(size_t(size * size * 6));
  glGetTextureImage(cube.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(vec4)),
                    pixels.data());
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

}  // namespace
}  // namespace mirage::test
