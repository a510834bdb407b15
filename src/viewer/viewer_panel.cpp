#include "viewer/viewer_panel.h"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <imgui.h>

#include "viewer/viewer_assignment.h"

namespace mirage {

namespace {

std::string valueOf(const ViewerState& state, const ParamSpec& spec) {
  auto it = state.params.find(spec.name);
  return it == state.params.end() ? spec.default_value : it->second;
}

void setValue(ViewerState& state, const ParamSpec& spec, const std::string& value) {
  if (valueOf(state, spec) == value) return;
  state.params[spec.name] = value;
  state.method_changed = true;
}

// One parameter as a control clamped to its range; the method is remade when an edit ends (a
// drag re-creating captures at every step would stall the window).
void parameterControl(ViewerState& state, const ParamSpec& spec) {
  const std::string label = spec.name;
  const std::string value = valueOf(state, spec);
  switch (spec.type) {
    case ParamSpec::Type::kInt: {
      int v = std::stoi(value);
      const float speed = float(std::max(1.0, (spec.max - spec.min) / 400.0));
      ImGui::DragInt(label.c_str(), &v, speed, int(spec.min), int(spec.max), "%d",
                     ImGuiSliderFlags_AlwaysClamp);
      if (ImGui::IsItemDeactivatedAfterEdit()) setValue(state, spec, std::to_string(v));
      break;
    }
    case ParamSpec::Type::kFloat: {
      float v = std::stof(value);
      const float speed = float(std::max(1e-4, (spec.max - spec.min) / 400.0));
      ImGui::DragFloat(label.c_str(), &v, std::min(speed, 0.01f), float(spec.min), float(spec.max),
                       "%.4g", ImGuiSliderFlags_AlwaysClamp);
      if (ImGui::IsItemDeactivatedAfterEdit()) setValue(state, spec, fmt::format("{}", v));
      break;
    }
    case ParamSpec::Type::kChoice:
      if (ImGui::BeginCombo(label.c_str(), value.c_str())) {
        for (const std::string& c : spec.choices)
          if (ImGui::Selectable(c.c_str(), c == value)) setValue(state, spec, c);
        ImGui::EndCombo();
      }
      break;
    case ParamSpec::Type::kText: {
      // Applied on Enter: a half-typed assignment is no assignment.
      char buffer[1024] = {};
      value.copy(buffer, sizeof(buffer) - 1);
      if (ImGui::InputText(label.c_str(), buffer, sizeof(buffer),
                           ImGuiInputTextFlags_EnterReturnsTrue))
        setValue(state, spec, buffer);
      break;
    }
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\n(%s, default %s)", spec.help.c_str(), spec.rangeText().c_str(),
                      spec.default_value.c_str());
}

void methodSection(ViewerState& state) {
  if (ImGui::BeginCombo("method", state.method.c_str())) {
    for (const std::string& name : methodNames())
      if (ImGui::Selectable(name.c_str(), name == state.method) && name != state.method) {
        state.method = name;
        state.method_changed = true;
      }
    ImGui::EndCombo();
  }
  if (ImGui::SliderInt("order K", &state.settings.order, 0, kMaxOrder, "%d",
                       ImGuiSliderFlags_AlwaysClamp))
    state.method_changed = true;
  if (ImGui::Checkbox("mip-mapped lookups", &state.settings.mip)) state.method_changed = true;
  const std::vector<ParamSpec>& params = findMethod(state.method).info.params;
  if (!params.empty() && ImGui::TreeNode("parameters")) {
    for (const ParamSpec& spec : params) parameterControl(state, spec);
    if (ImGui::Button("defaults")) {
      for (const ParamSpec& spec : params) setValue(state, spec, spec.default_value);
    }
    ImGui::TreePop();
  }
}

void sceneSection(const Scene& scene, ViewerState& state) {
  const std::string current = scene.cameras[size_t(state.camera_index)].name;
  if (ImGui::BeginCombo("camera", current.c_str())) {
    for (size_t i = 0; i < scene.cameras.size(); ++i)
      if (ImGui::Selectable(scene.cameras[i].name.c_str(), int(i) == state.camera_index)) {
        state.camera_index = int(i);
        state.camera_reset_requested = true;
      }
    ImGui::EndCombo();
  }
  ImGui::Checkbox("play", &state.clock.playing);
  ImGui::SameLine();
  if (ImGui::Button("restart")) state.clock.restart();
  ImGui::DragFloat("time", &state.clock.time, 0.01f, 0.0f, 1e6f, "%.3f s",
                   ImGuiSliderFlags_AlwaysClamp);
  ImGui::SliderFloat("speed", &state.clock.speed, 0.0f, 8.0f, "%.2fx");
  if (scene.animated()) ImGui::TextDisabled("the scene repeats within %.2f s", scene.duration());
  if (ImGui::Button(state.recording ? "stop recording (P)" : "record path (P)"))
    state.record_toggle_requested = true;
  ImGui::SameLine();
  if (ImGui::Button(state.playing_path ? "stop path (L)" : "play path (L)"))
    state.playback_toggle_requested = true;
  if (ImGui::Button("screenshot (F12)")) state.screenshot_requested = true;
  ImGui::SameLine();
  if (ImGui::Checkbox("vsync", &state.vsync)) state.vsync_changed = true;
}

void truthSection(ViewerState& state) {
  int mode = int(state.output.truth);
  ImGui::RadioButton("off", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("split", &mode, 1);
  ImGui::SameLine();
  ImGui::RadioButton("flip (G)", &mode, 2);
  state.output.truth = TruthMode(mode);
  ImGui::Checkbox("error heat map (H)", &state.output.heatmap);
  if (state.output.truth == TruthMode::kSplit)
    ImGui::SliderFloat("split", &state.output.split, 0.0f, 1.0f, "%.2f");
  if (state.output.heatmap)
    ImGui::SliderFloat("heat max", &state.output.heat_max, 0.01f, 1.0f, "%.2f");
  ImGui::SliderInt("resolution 1/n", &state.truth_divisor, 1, 8, "%d",
                   ImGuiSliderFlags_AlwaysClamp);
  ImGui::TextUnformatted(state.truth_status.c_str());
  if (std::isfinite(state.psnr))
    ImGui::Text("PSNR on reflector pixels: %.2f dB", state.psnr);
  else if (std::isinf(state.psnr))
    ImGui::Text("PSNR on reflector pixels: identical");
}

void statsSection(const ViewerState& state) {
  const FrameReadout& r = state.readout;
  ImGui::Text("%dx%d: %.1f fps (%.2f ms a frame)", state.size.x, state.size.y,
              r.loop_ms > 0.0 ? 1000.0 / r.loop_ms : 0.0, r.loop_ms);
  ImGui::Text("method %.2f ms: update %.2f, render %.2f", r.frame_ms, r.update_ms, r.render_ms);
  ImGui::Text("order rendered %d, reflector pixels %zu", r.order_rendered, r.reflector_pixels);
  if (!r.fallback.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f), "drawn by envmap: %s", r.fallback.c_str());
  for (const auto& [name, value] : r.counts) ImGui::Text("%s: %g", name.c_str(), value);
  ImGui::TextDisabled("GL objects held: %ld", r.gl_handles);
}

}  // namespace

void drawViewerPanel(const Scene& scene, ViewerState& state) {
  // A column at the left, never taller than the window (it scrolls), the frame beside it.
  const ImGuiIO& io = ImGui::GetIO();
  const float scale = io.FontGlobalScale;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(300 * scale, 0),
                                      ImVec2(420 * scale, io.DisplaySize.y - 16));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("mirage", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushItemWidth(150 * scale);
  ImGui::Text("%s", scene.name.c_str());
  if (!state.selected.empty()) ImGui::Text("selected: %s (F frames it)", state.selected.c_str());
  reflectorTechniqueControl(scene, state);
  if (ImGui::CollapsingHeader("method", ImGuiTreeNodeFlags_DefaultOpen)) methodSection(state);
  if (ImGui::CollapsingHeader("scene")) sceneSection(scene, state);
  if (ImGui::CollapsingHeader("ground truth", ImGuiTreeNodeFlags_DefaultOpen)) truthSection(state);
  if (ImGui::CollapsingHeader("statistics", ImGuiTreeNodeFlags_DefaultOpen)) statsSection(state);
  if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
  ImGui::TextDisabled(
      "drag: orbit (left), pan (right/middle); wheel: dolly; WASD QE: fly (shift: faster)\n"
      "click: select; F: frame it; R: reset; C: next camera; M/N: next/previous method\n"
      "space: play/pause; G: ground truth; H: heat map; P/L: record/play path; F12: shot");
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace mirage
