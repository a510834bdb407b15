// What the viewer writes: screenshots (the frame as shown, with a camera file that reproduces
// it), recorded camera paths, recorded events, and the run's report.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "scene/camera_file.h"
#include "viewer/viewer_app.h"

namespace mirage {

namespace {

namespace fs = std::filesystem;

// dir/<stem>-<n><extension> with the first n from 1 that no file has.
std::string freshName(const std::string& dir, const std::string& stem, const std::string& ext) {
  for (int n = 1;; ++n) {
    const fs::path p = fs::path(dir.empty() ? "." : dir) / fmt::format("{}-{}{}", stem, n, ext);
    std::error_code ec;
    if (!fs::exists(p, ec)) return p.string();
  }
}

// "shot.png" -> "shot.camera.json".
std::string cameraFileFor(const std::string& image) {
  fs::path p(image);
  return (p.parent_path() / (p.stem().string() + ".camera.json")).string();
}

nlohmann::json summary(std::vector<double> v) {
  if (v.empty()) return nullptr;
  std::sort(v.begin(), v.end());
  auto at = [&](double q) { return v[size_t(q * double(v.size() - 1) + 0.5)]; };
  return {{"min", v.front()}, {"median", at(0.5)}, {"p95", at(0.95)}};
}

nlohmann::json countsJson(const gpu::ObjectCounts& c) {
  return {{"buffers", c.buffers},           {"textures", c.textures},
          {"framebuffers", c.framebuffers}, {"vertex_arrays", c.vertex_arrays},
          {"programs", c.programs},         {"shaders", c.shaders},
          {"queries", c.queries},           {"total", c.total()}};
}

}  // namespace

// A .png is what the window shows (read back from its framebuffer: the display shader's
// output, with or without the panel); an .exr the method's linear frame. Its camera (and the
// time) go beside it, so that `mirage render --camera-path <it>.camera.json` redraws it.
void ViewerApp::screenshot(ivec2 size, const std::string& path) {
  if (path.ends_with(".png")) {
    Image shown(size.x, size.y);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, shown.data());
    shown.flipVertically();
    writePng(path, shown);
  } else {
    writeImage(path, downsample(renderer_->read(), state_.settings.pixel_scale).color,
               options_.display);
  }
  CameraDesc camera = camera_.desc();
  camera.name = "screenshot";
  saveCameraFile(cameraFileFor(path), camera, state_.clock.time);
}

void ViewerApp::takeShot(ivec2 size) {
  state_.screenshot_requested = false;
  const std::string path =
      freshName(options_.screenshot_dir, scene_.name + "-" + method_name_, ".png");
  try {
    screenshot(size, path);
    state_.message = "wrote " + path + " and its camera";
  } catch (const std::exception& e) {
    state_.message = e.what();
  }
  spdlog::info("view: {}", state_.message);
}

void ViewerApp::toggleRecording() {
  if (!recorder_.recording()) {
    recorder_.start(camera_.desc());
    state_.message = "recording the camera path (P stops)";
    return;
  }
  const std::optional<CameraDesc> path = recorder_.stop(camera_.desc());
  if (!path) {
    state_.message = "the recording was too short for a path";
    return;
  }
  const std::string file = !options_.record_path.empty()
                               ? options_.record_path
                               : freshName(options_.screenshot_dir, scene_.name + "-path", ".json");
  try {
    // What is written must read back: the recorded keys go through the same checks as a file.
    const std::string text = cameraFileText(*path);
    parseCameraFile(file, text);
    writeFileAtomic(file, text);
    loaded_path_ = path;
    state_.message = fmt::format("wrote {} ({} keys, {:.2f} s; L plays it)", file,
                                 path->path.keys.size(), path->path.duration());
  } catch (const std::exception& e) {
    state_.message = e.what();
  }
  spdlog::info("view: {}", state_.message);
}

void ViewerApp::togglePlayback() {
  if (recorder_.playing()) {
    recorder_.stopPlaying();
  } else if (loaded_path_) {
    recorder_.play(*loaded_path_);
  } else {
    state_.message = "no camera path to play (P records one, --play-path loads one)";
  }
}

void ViewerApp::writeReport() const {
  if (options_.report.empty()) return;
  nlohmann::json j;
  j["scene"] = scene_.name;
  j["frames"] = frame_ms_.size();
  j["size"] = {state_.size.x, state_.size.y};
  j["method"] = method_name_;
  j["methods_shown"] = methods_shown_;
  j["time"] = state_.clock.time;
  j["camera"] = nlohmann::json::parse(cameraFileText(camera_.desc()));
  j["frame_ms"] = summary(frame_ms_);
  j["update_ms"] = summary(update_ms_);
  j["render_ms"] = summary(render_ms_);
  j["loop_ms"] = summary(loop_ms_);  // frame to frame: the method's frame, output, panel, swap
  j["counts_last_frame"] = state_.readout.counts;
  j["gl_handles"] = {{"first_frame", countsJson(handles_first_)},
                     {"last_frame", countsJson(handles_last_)}};
  j["gl_objects"] = {{"first_frame", countsJson(objects_first_)},
                     {"last_frame", countsJson(objects_last_)}};
  nlohmann::json switches = nlohmann::json::array();
  for (const auto& [method, counts] : objects_after_switch_)
    switches.push_back({{"method", method}, {"gl_objects", countsJson(counts)}});
  j["gl_objects_after_switch"] = switches;
  j["truth"] = {{"mode", truthModeName(state_.output.truth)},
                {"heatmap", state_.output.heatmap},
                {"level", truth_image_.level},
                {"status", state_.truth_status}};
  // JSON has no infinity: identical images say "inf"; no reflector (NaN) is null.
  j["psnr_reflector"] = std::isfinite(state_.psnr) ? nlohmann::json(state_.psnr)
                        : std::isinf(state_.psnr)  ? nlohmann::json("inf")
                                                   : nlohmann::json(nullptr);
  j["selected"] = state_.selected;
  j["message"] = state_.message;
  writeFileAtomic(options_.report, j.dump(2) + "\n");
}

void ViewerApp::writeRecordedEvents() const {
  if (options_.record_events.empty()) return;
  writeFileAtomic(options_.record_events, eventScriptText(recorded_events_));
}

}  // namespace mirage
