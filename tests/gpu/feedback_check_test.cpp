// The feedback-loop guard (gpu/feedback_check.h): it sees a sampled texture that is an attachment
// of the draw framebuffer, colour or depth, and not one on another level or another texture; and
// with it on, every method draws every frame of every built-in scene tested here without a loop.
#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu/feedback_check.h"
#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "methods/frame.h"
#include "methods/method.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

class FeedbackCheck : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    was_on_ = gpu::feedbackChecks();
    gpu::setFeedbackChecks(true);
  }
  void TearDown() override {
    gpu::setFeedbackChecks(was_on_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    GlTest::TearDown();
  }
  bool was_on_ = false;
};

// The viewer's output program samples unit 0 (its u_frame).
gpu::Program unitZeroReader() {
  return gpu::Program::graphics("render/shaders/fullscreen.vert", "viewer/display.frag");
}

TEST_F(FeedbackCheck, SeesASampledColourAttachment) {
  gpu::Texture target = gpu::Texture::create2D(GL_RGBA16F, 4, 4);
  gpu::Texture other = gpu::Texture::create2D(GL_RGBA16F, 4, 4);
  gpu::Framebuffer fbo;
  fbo.attachColor(0, target);
  fbo.bind();
  const gpu::Program program = unitZeroReader();
  program.use();
  other.bind(0);
  EXPECT_NO_THROW(gpu::checkFeedback());
  target.bind(0);
  EXPECT_THROW(gpu::checkFeedback(), RuntimeError);
  gpu::setFeedbackChecks(false);
  EXPECT_NO_THROW(gpu::checkFeedback());
}

TEST_F(FeedbackCheck, SeesASampledDepthAttachmentEvenWithoutDepthWrites) {
  gpu::Texture color = gpu::Texture::create2D(GL_RGBA16F, 4, 4);
  gpu::Texture depth = gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, 4, 4);
  gpu::Framebuffer fbo;
  fbo.attachColor(0, color);
  fbo.attachDepth(depth);
  fbo.bind();
  const gpu::Program program = unitZeroReader();
  program.use();
  depth.bind(0);
  glDepthMask(GL_FALSE);  // masked writes do not make the read defined (GL 4.5 §9.3.1)
  EXPECT_THROW(gpu::checkFeedback(), RuntimeError);
  glDepthMask(GL_TRUE);
}

TEST_F(FeedbackCheck, AllowsAnotherLevelOfTheAttachedTexture) {
  gpu::Texture mips = gpu::Texture::create2D(GL_RGBA16F, 8, 8, 2);
  mips.setFilter(GL_NEAREST, GL_NEAREST);  // reads level 0 (the base level) only
  gpu::Framebuffer fbo;
  fbo.attachColor(0, mips, 1);
  fbo.bind();
  const gpu::Program program = unitZeroReader();
  program.use();
  mips.bind(0);
  EXPECT_NO_THROW(gpu::checkFeedback());
  mips.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);  // now level 1 can be read too
  EXPECT_THROW(gpu::checkFeedback(), RuntimeError);
}

// Every method, orders 1 and 2, on scenes with planar, curved and several reflectors: each draw
// is checked (GpuScene::draw, the background and the viewer's output call checkFeedback()).
TEST_F(FeedbackCheck, NoMethodDrawsWithAFeedbackLoop) {
  const ivec2 size(96, 64);
  for (const char* name : {"sphere-over-checker", "mirror-room", "teapot-sphere"}) {
    const Scene scene = makeBuiltinScene(name);
    FrameRenderer renderer(scene, size);
    const View view(scene.camera(), size);
    for (const std::string& method : parseMethodList("all"))
      for (int order : {1, 2}) {
        SCOPED_TRACE(std::string(name) + " " + method + " order " + std::to_string(order));
        FrameSettings settings;
        settings.order = order;
        auto m = renderer.createMethod(method, {}, settings);
        EXPECT_NO_THROW(renderer.render(*m, view, 0.0f, settings));
      }
  }
}

}  // namespace
}  // namespace mirage::test
