#include "viewer/viewer_app.h"

#include <chrono>
#include <cmath>
#include <thread>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <spdlog/spdlog.h>

#include "core/error.h"
#include "core/interrupt.h"
#include "core/supersample.h"
#include "core/timer.h"
#include "eval/metrics.h"
#include "gpu/framebuffer.h"
#include "viewer/viewer_assignment.h"
#include "viewer/viewer_panel.h"

namespace mirage {

namespace {

ViewerApp* appOf(GLFWwindow* window) {
  return static_cast<ViewerApp*>(glfwGetWindowUserPointer(window));
}

// Our callbacks go in before Dear ImGui's backend, which calls them after its own.
void installCallbacks(GLFWwindow* window, ViewerApp* app) {
  glfwSetWindowUserPointer(window, app);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_REPEAT) return;
    appOf(w)->queue({InputEvent::Type::kKey, key, action == GLFW_PRESS, vec2(0.0f)});
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    if (button > 2) return;
    appOf(w)->queue({InputEvent::Type::kButton, button, action == GLFW_PRESS, vec2(0.0f)});
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    appOf(w)->queue({InputEvent::Type::kMove, 0, false, vec2(float(x), float(y))});
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
    appOf(w)->queue({InputEvent::Type::kScroll, 0, false, vec2(float(x), float(y))});
  });
}

float contentScale(GLFWwindow* window) {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window, &x, &y);
  return std::clamp(std::max(x, y), 1.0f, 4.0f);
}

}  // namespace

ImGuiSession::ImGuiSession(GLFWwindow* window, float scale) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the user's files
  // High-DPI displays: the panel scaled with the monitor's content scale.
  io.FontGlobalScale = scale;
  ImGui::GetStyle().ScaleAllSizes(scale);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

ViewerApp::ViewerApp(const Scene& scene, const ViewerOptions& options)
    : scene_(scene),
      options_(options),
      window_(gpu::WindowOptions{options.size, "mirage — " + scene.name, true, options.vsync}),
      imgui_((installCallbacks(window_.window(), this), window_.window()),
             contentScale(window_.window())),
      camera_(options.camera) {
  state_.method = options.method;
  state_.params = options.params;
  state_.settings = options.settings;
  state_.clock.start = state_.clock.time = options.time;
  state_.clock.playing = options.play;
  state_.camera_index = options.camera_index;
  state_.output = options.output;
  state_.truth_divisor = options.truth_divisor;
  state_.vsync = options.vsync;
  output_ = std::make_unique<ViewerOutput>();
  script_ = options.events;
  if (options.play_path) {
    loaded_path_ = options.play_path;
    recorder_.play(*loaded_path_);
  }
  if (!options.record_path.empty()) recorder_.start(camera_.desc());
}

ViewerApp::~ViewerApp() {
  truth_.reset();  // joins its thread before the scene goes
  glfwSetWindowUserPointer(window_.window(), nullptr);
}

int ViewerApp::run() {
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  const bool scripted_run = options_.frames > 0;
  // Ctrl-C closes the window as Escape does: what was recorded and the report are still written,
  // then Interrupted goes on to main (exit 128 + the signal).
  try {
    for (frame_ = 0; !window_.shouldClose() && !interruptRequested(); ++frame_) {
      glfwPollEvents();
      const auto now = Clock::now();
      // A set number of frames steps 1/60 s each, so that a script replays the same everywhere.
      const double wall = std::chrono::duration<double>(now - last).count();
      const double seconds = scripted_run ? 1.0 / 60.0 : std::min(wall, 0.25);
      if (frame_ > 1) {  // the whole last frame: the method's, the output pass, the panel, the swap
        loop_ms_.push_back(1000.0 * wall);
        state_.readout.loop_ms +=
            (frame_ == 2 ? 1.0 : 0.1) * (1000.0 * wall - state_.readout.loop_ms);
      }
      last = now;
      handleEvents(frame_);
      applyRequests();
      if (frame_ > 0) {
        state_.clock.advance(seconds);
        moveCamera(seconds);
      }
      const ivec2 size = window_.framebufferSize();
      if (size.x <= 0 || size.y <= 0) {  // minimised: wait for the window to come back
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      if (!ensureStage(size)) break;
      const bool last_frame = scripted_run && frame_ + 1 >= options_.frames;
      renderFrame(size);
      updateTruth(size, last_frame);
      present(size);
      if (last_frame && !options_.screenshot.empty() && !options_.screenshot_panel)
        screenshot(size, options_.screenshot);
      if (state_.screenshot_requested) takeShot(size);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      drawViewerPanel(scene_, state_);
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (last_frame && !options_.screenshot.empty() && options_.screenshot_panel)
        screenshot(size, options_.screenshot);
      window_.swapBuffers();
      if (frame_ == 0) {
        handles_first_ = gpu::liveHandles();
        objects_first_ = gpu::glObjects();
      }
      handles_last_ = gpu::liveHandles();
      if (method_made_ && frame_ > 0 && !options_.report.empty())
        objects_after_switch_.push_back({method_name_, gpu::glObjects()});
      method_made_ = false;
      if (last_frame) break;
    }
  } catch (const Interrupted&) {  // mid-frame; interruptRequested() says so below
  }
  objects_last_ = gpu::glObjects();
  if (recorder_.recording()) toggleRecording();
  writeReport();
  writeRecordedEvents();
  checkInterrupt();
  return 0;
}

void ViewerApp::applyRequests() {
  if (state_.vsync_changed) {
    window_.setVsync(state_.vsync);
    state_.vsync_changed = false;
  }
  if (state_.camera_reset_requested) {
    camera_.reset(scene_.cameras[size_t(state_.camera_index)].at(state_.clock.time));
    recorder_.stopPlaying();
    state_.camera_reset_requested = false;
  }
  if (state_.record_toggle_requested) toggleRecording();
  if (state_.playback_toggle_requested) togglePlayback();
  state_.record_toggle_requested = state_.playback_toggle_requested = false;
  state_.recording = recorder_.recording();
  state_.playing_path = recorder_.playing();
}

// The renderer for this size and the method asked for; a method that cannot be made (a value
// its construction refuses, a driver limit) leaves the last one in place and says why.
bool ViewerApp::ensureStage(ivec2 size) {
  const ivec2 frame_size = supersampledSize(size, state_.settings.pixel_scale);
  if (!renderer_ || renderer_->size() != frame_size) {
    if (const int largest = gpu::maxFrameSide(); std::max(frame_size.x, frame_size.y) > largest)
      throwInput(
          "--ssaa {}: a {}x{} window needs a {}x{} frame, beyond this driver's largest frame "
          "side {} (use a smaller --ssaa or window)",
          state_.settings.pixel_scale, size.x, size.y, frame_size.x, frame_size.y, largest);
    method_.reset();
    renderer_ = std::make_unique<FrameRenderer>(scene_, frame_size);
    if (!truth_) {
      const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
      truth_ =
          std::make_unique<TruthRenderer>(scene_, renderer_->environment(), std::max(1, cores - 1));
    }
  }
  if (method_ && !state_.method_changed) return true;
  seedAssignment(scene_, state_, method_name_);
  try {
    auto made = renderer_->createMethod(state_.method, state_.params, state_.settings);
    method_ = std::move(made);
    method_name_ = state_.method;
    method_params_ = state_.params;
    methods_shown_.push_back(method_name_);
    method_made_ = true;
    state_.message.clear();
  } catch (const std::exception& e) {
    if (!method_) throw;  // nothing to fall back on: the first method must be made
    state_.message = e.what();
    spdlog::warn("view: {}", e.what());
    state_.method = method_name_;
    state_.params = method_params_;
  }
  state_.method_changed = false;
  return true;
}

void ViewerApp::renderFrame(ivec2 size) {
  gpu::FrameTimer timer(gpu::Clock::kWall);
  // --ssaa N: the frame has N x N sub-pixels per window pixel; the output pass averages them.
  const View view(camera_.desc(), supersampledSize(size, state_.settings.pixel_scale));
  try {
    renderer_->render(*method_, view, state_.clock.time, state_.settings, &timer,
                      &state_.readout.counts);
  } catch (const InputError& e) {
    // A setting the method refuses at render time (an order below its minimum): back to 1.
    state_.message = e.what();
    state_.settings.order =
        std::max(state_.settings.order, findMethod(method_name_).info.min_order);
    state_.method_changed = true;
    return;
  }
  const gpu::FrameTimes t = timer.takeResults().front();
  const double update = t.part_ms[0], render = t.part_ms[1] + t.part_ms[2];
  frame_ms_.push_back(t.total_ms);
  update_ms_.push_back(update);
  render_ms_.push_back(render);
  FrameReadout& r = state_.readout;
  const double k = frame_ == 0 ? 1.0 : 0.1;  // smoothed for reading
  r.frame_ms += k * (t.total_ms - r.frame_ms);
  r.update_ms += k * (update - r.update_ms);
  r.render_ms += k * (render - r.render_ms);
  r.gl_handles = gpu::liveHandles().total();
  r.order_rendered = method_->orderRendered(state_.settings.order);
  r.fallback = method_->fallbackReason();
  if (frame_ % 15 == 0)
    r.reflector_pixels = countNonZero(
        majorityDownsample(renderer_->target().readIds(), state_.settings.pixel_scale));
  state_.size = size;
}

TruthRequest ViewerApp::truthRequest(ivec2 size) const {
  TruthRequest request;
  request.camera = camera_.desc();
  request.size = size;
  request.divisor = std::clamp(state_.truth_divisor, 1, 8);
  request.ssaa = state_.settings.pixel_scale;
  request.time = state_.clock.time;
  request.order = state_.settings.order;
  return request;
}

void ViewerApp::updateTruth(ivec2 size, bool last_frame) {
  const bool wanted = state_.output.truth != TruthMode::kOff || state_.output.heatmap;
  if (!wanted) {
    truth_->cancel();
    state_.truth_status = "off";
    state_.psnr = std::nan("");
    return;
  }
  const TruthRequest request = truthRequest(size);
  truth_->request(request);
  // A scripted run's last frame waits for the finished reference, so that what it writes does
  // not depend on the machine's speed.
  while (last_frame &&
         !(truth_image_.request == request && truth_image_.level == TruthRequest::kLevels - 1)) {
    if (!truth_->failure().empty()) break;
    if (!truth_->takeNewer(truth_image_))
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    else
      output_->setTruth(truth_image_);
  }
  if (const std::string why = truth_->failure(); !why.empty()) {
    state_.truth_status = "the reference failed: " + why;
    return;
  }
  const bool fresh = truth_->takeNewer(truth_image_);
  if (fresh) output_->setTruth(truth_image_);
  const bool current = truth_image_.level >= 0 && truth_image_.request == request;
  if (current && (fresh || frame_ % 30 == 0 || last_frame))
    state_.psnr = truthPsnr(renderer_->read(), truth_image_, options_.display);
  if (!current) state_.psnr = std::nan("");
  const ivec2 s =
      truth_image_.level >= 0 ? truth_image_.request.levelSize(truth_image_.level) : ivec2(0);
  const int working = truth_->working();
  state_.truth_status =
      truth_image_.level < 0
          ? "rendering..."
          : fmt::format(
                "{} {}x{}, {} spp, {:.0f} ms{}", current ? "reference" : "stale reference", s.x,
                s.y, truth_image_.request.levelSpp(truth_image_.level), truth_image_.ms,
                working >= 0
                    ? fmt::format(" (refining: level {} of {})", working + 1, TruthRequest::kLevels)
                    : "");
}

void ViewerApp::present(ivec2 size) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  OutputSettings output = state_.output;
  output.display = options_.display;
  output.ssaa = state_.settings.pixel_scale;
  output_->draw(renderer_->target().color(), size, output);
}

int runViewer(const Scene& scene, const ViewerOptions& options) {
  ViewerApp app(scene, options);
  return app.run();
}

}  // namespace mirage
