// The viewer's reflection assignment (method `mixed`): the selected reflector's technique chosen
// live in the panel, rewriting the `--assign` text the method is remade with.
#pragma once

#include "scene/scene.h"
#include "viewer/viewer_state.h"

namespace mirage {

// The assignment the viewer draws now: mixed's `assign` text, or the scene's "reflections", or
// (another method) every reflector by that method.
std::vector<ReflectionRule> viewerRules(const Scene& scene, const ViewerState& state);

// Switching to `mixed` with no assignment anywhere: every reflector by `previous` (the frame
// stays as it was), or envmap when `previous` draws whole frames.
void seedAssignment(const Scene& scene, ViewerState& state, const std::string& previous);

// The panel's control for the selected reflector's technique (nothing when none is selected).
void reflectorTechniqueControl(const Scene& scene, ViewerState& state);

}  // namespace mirage
