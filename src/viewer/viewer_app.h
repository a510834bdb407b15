// The viewer's parts behind runViewer (viewer.h): one class, its loop and rendering in
// viewer_app.cpp, its input in viewer_input.cpp, the files it writes in viewer_files.cpp.
#pragma once

#include <array>
#include <memory>
#include <set>
#include <vector>

#include "gpu/object_count.h"
#include "gpu/window_context.h"
#include "raytrace/ray_scene.h"
#include "viewer/input.h"
#include "viewer/path_recorder.h"
#include "viewer/truth_renderer.h"
#include "viewer/viewer.h"
#include "viewer/viewer_camera.h"
#include "viewer/viewer_state.h"

namespace mirage {

// Dear ImGui bound to one window for its lifetime.
class ImGuiSession {
 public:
  ImGuiSession(GLFWwindow* window, float content_scale);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

class ViewerApp {
 public:
  ViewerApp(const Scene& scene, const ViewerOptions& options);
  ~ViewerApp();
  int run();

  // The window's events land here (GLFW callbacks), to be handled at the next frame.
  void queue(const InputEvent& event) { window_events_.push_back(event); }

 private:
  // viewer_app.cpp: the frame.
  void applyRequests();
  bool ensureStage(ivec2 size);
  void renderFrame(ivec2 size);
  void updateTruth(ivec2 size, bool last_frame);
  void present(ivec2 size);
  TruthRequest truthRequest(ivec2 size) const;
  // viewer_input.cpp: events and what they do.
  void handleEvents(int frame);
  void handle(const InputEvent& event, bool scripted);
  void keyPressed(int key);
  void moveCamera(double seconds);
  void pick(vec2 cursor);
  void cycleMethod(int step);
  // viewer_files.cpp: what the viewer writes.
  void screenshot(ivec2 size, const std::string& path);
  void takeShot(ivec2 size);
  void toggleRecording();
  void togglePlayback();
  void writeReport() const;
  void writeRecordedEvents() const;

  const Scene& scene_;
  ViewerOptions options_;
  gpu::WindowContext window_;
  ImGuiSession imgui_;
  ViewerState state_;
  ViewerCamera camera_;
  PathRecorder recorder_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::unique_ptr<Method> method_;
  std::string method_name_;  // what method_ is; state_.method is what is asked for
  std::map<std::string, std::string> method_params_;
  std::unique_ptr<ViewerOutput> output_;
  std::unique_ptr<TruthRenderer> truth_;
  TruthImage truth_image_;
  std::unique_ptr<RayScene> picker_;
  int selected_ = -1;
  std::optional<CameraDesc> loaded_path_;

  // Input.
  std::vector<InputEvent> window_events_;
  std::vector<ScriptedEvent> script_, recorded_events_;
  size_t script_next_ = 0;
  std::set<int> keys_down_;
  std::array<bool, 3> buttons_{};
  vec2 cursor_{0.0f}, press_at_{0.0f};
  bool dragged_ = false;
  int frame_ = 0;

  // Figures for --report.
  std::vector<double> frame_ms_, update_ms_, render_ms_, loop_ms_;
  std::vector<std::string> methods_shown_;
  gpu::ObjectCounts handles_first_, handles_last_, objects_first_, objects_last_;
  // At the end of each frame that showed a newly made method: the method and the objects.
  std::vector<std::pair<std::string, gpu::ObjectCounts>> objects_after_switch_;
  bool method_made_ = false;
};

}  // namespace mirage
