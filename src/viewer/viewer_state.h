// What the viewer's panel edits and shows: the method and its parameters, the scene clock, the
// ground truth's settings, and the last frame's readouts. The viewer acts on the requests
// (`*_requested`, `method_changed`) at the start of its next frame.
#pragma once

#include <limits>
#include <map>
#include <string>

#include "methods/frame.h"
#include "viewer/scene_clock.h"
#include "viewer/viewer_output.h"

namespace mirage {

struct FrameReadout {
  double frame_ms = 0.0, update_ms = 0.0, render_ms = 0.0;  // smoothed over recent frames
  double loop_ms = 0.0;                  // frame to frame, the panel and the swap included
  std::map<std::string, double> counts;  // the last frame's
  size_t reflector_pixels = 0;
  long gl_handles = 0;
  int order_rendered = 0;
  std::string fallback;  // why envmap draws in the method's place, or empty
};

struct ViewerState {
  // Edited by the panel (and keys).
  std::string method;
  std::map<std::string, std::string> params;  // given values by name (defaults elsewhere)
  FrameSettings settings;
  bool method_changed = false;
  SceneClock clock;
  int camera_index = 0;
  bool camera_reset_requested = false;
  OutputSettings output;
  int truth_divisor = 2;
  bool vsync = true, vsync_changed = false;
  bool screenshot_requested = false, record_toggle_requested = false,
       playback_toggle_requested = false;
  // Shown by the panel.
  FrameReadout readout;
  std::string truth_status;
  double psnr = std::numeric_limits<double>::quiet_NaN();  // on reflector pixels, current only
  std::string selected;                                    // the picked instance, or ""
  std::string message;                                     // the last error or notice
  bool recording = false, playing_path = false;
  ivec2 size{0};
};

}  // namespace mirage
