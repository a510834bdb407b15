// The viewer's input: events from the window or a script, handled alike (a script's are not
// held back by the panel, which never saw their cursor), and the keys' actions.
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "viewer/viewer_app.h"

namespace mirage {

namespace {
constexpr float kClickSlop = 3.0f;  // window units a press may move and still be a click
}

void ViewerApp::handleEvents(int frame) {
  std::vector<InputEvent> window_events = std::move(window_events_);
  window_events_.clear();
  for (const InputEvent& e : window_events) {
    // Only named keys can be written to an event script.
    if (!options_.record_events.empty() &&
        (e.type != InputEvent::Type::kKey || !keyName(e.code).empty()))
      recorded_events_.push_back({frame, e});
    handle(e, false);
  }
  while (script_next_ < script_.size() && script_[script_next_].frame <= frame)
    handle(script_[script_next_++].event, true);
}

void ViewerApp::handle(const InputEvent& e, bool scripted) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool panel_mouse = !scripted && io.WantCaptureMouse;
  const bool panel_keys = !scripted && io.WantCaptureKeyboard;
  // Window units to framebuffer pixels (they differ on high-DPI displays).
  int ww = 1, wh = 1;
  glfwGetWindowSize(window_.window(), &ww, &wh);
  const ivec2 fb = window_.framebufferSize();
  const vec2 to_pixels(float(fb.x) / float(std::max(ww, 1)), float(fb.y) / float(std::max(wh, 1)));
  switch (e.type) {
    case InputEvent::Type::kMove: {
      const vec2 delta = (e.position - cursor_) * to_pixels;
      cursor_ = e.position;
      if (glm::length(cursor_ - press_at_) > kClickSlop) dragged_ = true;
      if (buttons_[0]) {
        camera_.orbit(delta);
        recorder_.stopPlaying();
      }
      if (buttons_[1] || buttons_[2]) {
        camera_.pan(delta, float(fb.y));
        recorder_.stopPlaying();
      }
      break;
    }
    case InputEvent::Type::kButton:
      if (e.down && panel_mouse) break;  // a press on the panel is the panel's
      buttons_[size_t(std::clamp(e.code, 0, 2))] = e.down;
      if (e.down) {
        press_at_ = cursor_;
        dragged_ = false;
      } else if (e.code == 0 && !dragged_) {
        pick(cursor_ * to_pixels);
      }
      break;
    case InputEvent::Type::kScroll:
      if (panel_mouse) break;
      camera_.dolly(e.position.y);
      recorder_.stopPlaying();
      break;
    case InputEvent::Type::kResize:
      glfwSetWindowSize(window_.window(), int(e.position.x), int(e.position.y));
      break;
    case InputEvent::Type::kKey:
      if (!e.down) {
        keys_down_.erase(e.code);
        break;
      }
      if (panel_keys) break;
      keys_down_.insert(e.code);
      keyPressed(e.code);
      break;
  }
}

void ViewerApp::keyPressed(int key) {
  switch (key) {
    case GLFW_KEY_R:
      state_.camera_reset_requested = true;
      break;
    case GLFW_KEY_F:
      camera_.frame(selected_ >= 0 ? scene_.instanceBounds(selected_, state_.clock.time)
                                   : scene_.bounds(state_.clock.time));
      recorder_.stopPlaying();
      break;
    case GLFW_KEY_C:
      state_.camera_index = (state_.camera_index + 1) % int(scene_.cameras.size());
      state_.camera_reset_requested = true;
      break;
    case GLFW_KEY_M:
      cycleMethod(1);
      break;
    case GLFW_KEY_N:
      cycleMethod(-1);
      break;
    case GLFW_KEY_SPACE:
      state_.clock.playing = !state_.clock.playing;
      break;
    case GLFW_KEY_G:
      state_.output.truth = TruthMode((int(state_.output.truth) + 1) % 3);
      break;
    case GLFW_KEY_H:
      state_.output.heatmap = !state_.output.heatmap;
      break;
    case GLFW_KEY_P:
      state_.record_toggle_requested = true;
      break;
    case GLFW_KEY_L:
      state_.playback_toggle_requested = true;
      break;
    case GLFW_KEY_V:
      state_.vsync = !state_.vsync;
      state_.vsync_changed = true;
      break;
    case GLFW_KEY_F12:
      state_.screenshot_requested = true;
      break;
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window_.window(), GLFW_TRUE);
      break;
    default:
      break;
  }
}

void ViewerApp::cycleMethod(int step) {
  const std::vector<std::string> names = methodNames();
  const auto it = std::find(names.begin(), names.end(), state_.method);
  const int at = it == names.end() ? 0 : int(it - names.begin());
  const int n = int(names.size());
  state_.method = names[size_t(((at + step) % n + n) % n)];
  state_.method_changed = true;
}

// Fly with the held keys, or follow the camera path being played.
void ViewerApp::moveCamera(double seconds) {
  if (recorder_.playing()) {
    if (auto camera = recorder_.advance(seconds)) camera_.reset(*camera);
  } else {
    const auto held = [&](int key) { return keys_down_.count(key) ? 1.0f : 0.0f; };
    const vec3 direction(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                         held(GLFW_KEY_W) - held(GLFW_KEY_S));
    if (direction != vec3(0.0f)) {
      const bool fast = held(GLFW_KEY_LEFT_SHIFT) + held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
      // Half the scene's size a second; four times that with shift.
      const float speed =
          0.5f * std::max(scene_.bounds(0.0f).radius(), 1e-3f) * (fast ? 4.0f : 1.0f);
      camera_.fly(direction, speed, float(seconds));
    }
  }
  recorder_.record(camera_.desc(), seconds);
}

// The instance under `pixel` (framebuffer pixels, top-left origin), traced against the scene at
// the current time (the BVH built on the first click, rebuilt when the scene has moved).
void ViewerApp::pick(vec2 pixel) {
  if (!picker_) picker_ = std::make_unique<RayScene>(scene_);
  if (picker_->builtTime() != state_.clock.time) picker_->build(state_.clock.time);
  const View view(camera_.desc(), window_.framebufferSize());
  const RayHit hit = picker_->intersect(view.primaryRay(pixel.x, pixel.y));
  selected_ = hit.instance;
  state_.selected = selected_ >= 0 ? scene_.instances[size_t(selected_)].name : "";
}

}  // namespace mirage
