// `mirage view`: the interactive viewer — a window (GLFW) showing a scene through any registered
// method, an orbit camera, and a Dear ImGui panel to switch methods and the reflection order
// live, with the frame time and the method's counters. With `frames` > 0 it renders that many
// frames, writes the last one (`screenshot`) and returns: for scripts and tests.
#pragma once

#include <map>
#include <string>

#include "core/display.h"
#include "methods/frame.h"

namespace mirage {

struct ViewerOptions {
  CameraDesc camera;
  float time = 0.0f;
  std::string method = "envmap";
  std::map<std::string, std::string> params;
  FrameSettings settings;
  DisplaySettings display;
  ivec2 size{720, 512};
  int frames = 0;  // 0: until the window is closed
  std::string
      screenshot;  // with `frames`: the last frame, .png as shown in the window, .exr linear
  bool vsync = true;
};

// Throws InputError without a display (exit 2) and NoOpenGLError without OpenGL 4.5.
int runViewer(const Scene& scene, const ViewerOptions& options);

}  // namespace mirage
