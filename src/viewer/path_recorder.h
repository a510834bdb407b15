// Records the viewer's camera as a camera path (a key every 1/30 s of recording time, and one
// when recording stops) and plays a path back, for `mirage render|bench --camera-path` and for
// replays in the viewer. Recording time advances with the viewer's frame steps, so a path plays
// back at the speed it was recorded.
#pragma once

#include <optional>
#include <string>

#include "core/camera.h"

namespace mirage {

class PathRecorder {
 public:
  // Recording.
  void start(const CameraDesc& camera);
  // Adds the camera after `seconds` more of recording (keys at most 30 a second).
  void record(const CameraDesc& camera, double seconds);
  // Ends the recording: the path (at least two keys) or nothing when it was too short to move.
  std::optional<CameraDesc> stop(const CameraDesc& camera);
  bool recording() const { return recording_; }

  // Playback: the camera along `path` from its start; `advance` moves it on and returns the
  // camera, or nothing once the path has ended (playback then stops).
  void play(const CameraDesc& path);
  std::optional<CameraDesc> advance(double seconds);
  bool playing() const { return playing_; }
  void stopPlaying() { playing_ = false; }
  float playTime() const { return float(play_time_); }
  const CameraDesc& path() const { return path_; }

 private:
  CameraDesc recorded_, path_;
  double record_time_ = 0.0, last_key_time_ = 0.0;
  double play_time_ = 0.0;
  bool recording_ = false, playing_ = false;
};

}  // namespace mirage
