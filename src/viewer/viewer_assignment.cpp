#include "viewer/viewer_assignment.h"

#include <imgui.h>

#include "methods/assignment.h"
#include "methods/method.h"

namespace mirage {

namespace {

std::string assignValue(const ViewerState& state) {
  auto it = state.params.find(kAssignParam);
  return it == state.params.end() ? std::string() : it->second;
}

}  // namespace

std::vector<ReflectionRule> viewerRules(const Scene& scene, const ViewerState& state) {
  if (!findMethod(state.method).info.needs_assignment) return singleMethodRules(state.method, {});
  const std::string text = assignValue(state);
  return text.empty() ? scene.reflections : parseAssignText(text);
}

void seedAssignment(const Scene& scene, ViewerState& state, const std::string& previous) {
  if (!findMethod(state.method).info.needs_assignment || !assignValue(state).empty() ||
      !scene.reflections.empty())
    return;
  const bool keep = !previous.empty() && assignable(findMethod(previous).info);
  state.params[kAssignParam] = "*=" + (keep ? previous : std::string("envmap"));
}

void reflectorTechniqueControl(const Scene& scene, ViewerState& state) {
  int instance = -1;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == state.selected && scene.isReflector(int(i))) instance = int(i);
  if (instance < 0) return;
  std::string current;
  try {
    current = methodOf(resolveAssignment(scene, viewerRules(scene, state)), instance);
  } catch (const std::exception&) {
    return;  // an assignment being typed: the text field shows it
  }
  if (!ImGui::BeginCombo("its technique", current.c_str())) return;
  for (const MethodEntry& entry : methodRegistry()) {
    if (!assignable(entry.info)) continue;
    const std::string& name = entry.info.name;
    if (!ImGui::Selectable(name.c_str(), name == current) || name == current) continue;
    state.params[kAssignParam] =
        assignText(reassign(scene, viewerRules(scene, state), instance, name));
    state.method = "mixed";
    state.method_changed = true;
  }
  ImGui::EndCombo();
}

}  // namespace mirage
