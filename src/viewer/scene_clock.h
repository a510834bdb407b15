// The viewer's scene time: plays at a speed, pauses, restarts. A frame's step is the wall time
// since the last frame, or a fixed 1/60 s when the viewer runs a set number of frames (scripts
// and tests), so that a replayed script reaches the same times on any machine.
#pragma once

#include <algorithm>

namespace mirage {

struct SceneClock {
  float start = 0.0f;
  float time = 0.0f;
  float speed = 1.0f;  // scene seconds per second, 0..8
  bool playing = false;

  void advance(double seconds) {
    if (playing) time = std::max(0.0f, time + float(seconds) * speed);
  }
  void restart() { time = start; }
};

}  // namespace mirage
