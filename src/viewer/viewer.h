// `mirage view`: the interactive viewer — a window (GLFW) showing a scene through any registered
// method; an orbit / pan / dolly / fly camera; a Dear ImGui panel that switches methods, sets
// every parameter of the current one live within its range, plays the scene's time and shows
// the frame time split into update and render with the method's per-frame counts; the ray
// traced ground truth beside the frame (split or flip, refined in the background) with its error
// heat map and PSNR; camera paths recorded and played; screenshots with their camera.
// With `frames` > 0 it renders that many frames (fixed 1/60 s steps, an event script replayed),
// writes what it was asked to and returns: for scripts and tests.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/display.h"
#include "methods/frame.h"
#include "viewer/input.h"
#include "viewer/viewer_output.h"

namespace mirage {

struct ViewerOptions {
  CameraDesc camera;  // the camera at the start (the scene's, or --camera-path's)
  int camera_index = 0;
  float time = 0.0f;
  bool play = true;  // the scene's time runs from the start (when the scene moves)
  std::string method = "envmap";
  std::map<std::string, std::string> params;
  FrameSettings settings;
  DisplaySettings display;
  ivec2 size{720, 512};
  bool vsync = true;
  int frames = 0;                     // 0: until the window is closed
  std::string screenshot;             // with `frames`: the last frame, .png as shown, .exr linear
  bool screenshot_panel = false;      // the .png with the panel over it (for documentation)
  std::string screenshot_dir;         // where F12 writes (PNG + camera file)
  std::vector<ScriptedEvent> events;  // an event script to replay (--events)
  std::string record_events;          // the window's events are written here at exit
  std::string record_path;  // a camera path is recorded from the start, written here at exit
  std::optional<CameraDesc> play_path;  // a camera path played from the start (--play-path)
  std::string report;     // at exit: JSON with frame times, GL object counts, the camera
  OutputSettings output;  // the ground truth's mode, heat map, split
  int truth_divisor = 2;  // the reference's resolution: the frame's / this (1..8)
};

// Throws InputError without a display (exit 2) and NoOpenGLError without OpenGL 4.5.
int runViewer(const Scene& scene, const ViewerOptions& options);

}  // namespace mirage
