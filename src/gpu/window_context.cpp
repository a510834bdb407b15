#include "gpu/window_context.h"

#include <atomic>
#include <cstdlib>

#include "gpu/gl.h"  // before GLFW: epoxy replaces GL/gl.h
#include "gpu/keep_drivers_loaded.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <spdlog/spdlog.h>

#include "core/error.h"

namespace mirage::gpu {

namespace {

std::string& lastGlfwError() {
  static std::string error;
  return error;
}

void errorCallback(int code, const char* message) {
  lastGlfwError() = fmt::format("GLFW error 0x{:x}: {}", code, message ? message : "");
}

// glfwInit/glfwTerminate once per live window count.
std::atomic<int> g_windows{0};

}  // namespace

WindowContext::WindowContext(const WindowOptions& options) {
  glfwSetErrorCallback(errorCallback);
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    throwInput(
        "no display: a window needs an X server (set DISPLAY, or run under `xvfb-run -a`); "
        "the headless commands render, compare and bench need none");
  if (g_windows++ == 0 && !glfwInit()) {
    --g_windows;
    throwInput("cannot open the display '{}': {}", display ? display : "", lastGlfwError());
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  window_ =
      glfwCreateWindow(options.size.x, options.size.y, options.title.c_str(), nullptr, nullptr);
  if (!window_) {
    if (--g_windows == 0) glfwTerminate();
    throw NoOpenGLError("no OpenGL 4.5 core context for a window: " + lastGlfwError());
  }
  keepDriversLoaded();
  makeCurrent();
  try {
    queryInfo("GLFW window");
  } catch (...) {
    glfwDestroyWindow(window_);
    if (--g_windows == 0) glfwTerminate();
    throw;
  }
  if (options.debug) enableDebugOutput();
  setVsync(options.vsync);
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  if (--g_windows == 0) glfwTerminate();
}

void WindowContext::makeCurrent() {
  glfwMakeContextCurrent(window_);
}
bool WindowContext::shouldClose() const {
  return glfwWindowShouldClose(window_);
}
void WindowContext::swapBuffers() {
  glfwSwapBuffers(window_);
}
void WindowContext::setVsync(bool on) {
  glfwSwapInterval(on ? 1 : 0);
}

ivec2 WindowContext::framebufferSize() const {
  ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

}  // namespace mirage::gpu
