// An OpenGL 4.5 core context with a window (GLFW), for the interactive viewer. GLFW 3.3 needs an
// X display (Xvfb in tests). Without one, creation throws InputError (the viewer's exit code 2).
#pragma once

#include <memory>
#include <string>

#include "core/math.h"
#include "gpu/context.h"

struct GLFWwindow;

namespace mirage::gpu {

struct WindowOptions {
  ivec2 size{1280, 800};
  std::string title = "mirage";
  bool visible = true;
  bool vsync = true;
  bool debug = false;
};

class WindowContext final : public Context {
 public:
  explicit WindowContext(const WindowOptions& options);
  ~WindowContext() override;
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  void makeCurrent() override;
  GLFWwindow* window() const { return window_; }
  bool shouldClose() const;
  void swapBuffers();
  void setVsync(bool on);
  // Framebuffer size in pixels (differs from the window size on high-DPI displays).
  ivec2 framebufferSize() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace mirage::gpu
