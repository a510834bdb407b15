// The GLFW window context. These tests need an X display: ctest runs them under `xvfb-run -a`
// (test "WindowContextUnderXvfb"); run directly without DISPLAY they check the error path only.
#include <cstdlib>

#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu/gl.h"
#include "gpu/window_context.h"
#include "render/frame_target.h"
#include "support/gl_test.h"

namespace mirage::gpu {
namespace {

TEST(WindowContext, WithoutDisplaySaysSo) {
  if (test::haveDisplay()) GTEST_SKIP() << "a display is available";
  try {
    WindowContext window({});
    FAIL() << "a window opened without a display";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("xvfb-run"), std::string::npos) << e.what();
  }
}

TEST(WindowContext, OpensOpenGL45AndRenders) {
  MIRAGE_NEED_DISPLAY();
  WindowOptions options;
  options.size = {64, 48};
  options.visible = false;
  WindowContext window(options);
  EXPECT_GE(window.info().major * 10 + window.info().minor, 45) << window.info().version;
  EXPECT_EQ(window.framebufferSize(), ivec2(64, 48));
  // The shared GL objects work in this context too: clear a frame target and read it back.
  FrameTarget target({8, 4});
  target.bind();
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  Image color = target.readColor();
  EXPECT_FLOAT_EQ(color(3, 2).y, 0.5f);
  // The default framebuffer swaps.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  window.swapBuffers();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace mirage::gpu
