#include "viewer/path_recorder.h"

namespace mirage {

namespace {
constexpr double kKeyInterval = 1.0 / 30.0;
}

void PathRecorder::start(const CameraDesc& camera) {
  recorded_ = camera;
  recorded_.name = "recorded";
  recorded_.path.keys = {{0.0f, camera.position, camera.target}};
  record_time_ = last_key_time_ = 0.0;
  recording_ = true;
}

void PathRecorder::record(const CameraDesc& camera, double seconds) {
  if (!recording_) return;
  record_time_ += seconds;
  if (record_time_ - last_key_time_ < kKeyInterval - 1e-9) return;  // two 60 Hz frames count
  recorded_.path.keys.push_back({float(record_time_), camera.position, camera.target});
  last_key_time_ = record_time_;
}

std::optional<CameraDesc> PathRecorder::stop(const CameraDesc& camera) {
  if (!recording_) return std::nullopt;
  recording_ = false;
  auto& keys = recorded_.path.keys;
  const float end = float(record_time_);
  if (end > keys.back().time) keys.push_back({end, camera.position, camera.target});
  if (keys.size() < 2) return std::nullopt;
  recorded_.position = keys.front().position;
  recorded_.target = keys.front().target;
  return recorded_;
}

void PathRecorder::play(const CameraDesc& path) {
  path_ = path;
  play_time_ = path.path.start();
  playing_ = !path.path.empty();
}

std::optional<CameraDesc> PathRecorder::advance(double seconds) {
  if (!playing_) return std::nullopt;
  // Summed in double: fifteen float steps of 1/60 s miss 0.25 by an ulp, and the camera there
  // then differs from `render --time 0.25`'s.
  play_time_ += seconds;
  if (float(play_time_) > path_.path.end()) {
    playing_ = false;
    return path_.at(path_.path.end());
  }
  return path_.at(float(play_time_));
}

}  // namespace mirage
