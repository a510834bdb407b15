// The viewer's Dear ImGui panel: method, order and every parameter of the method as a control
// within its documented range; scene cameras; time (play, pause, speed); the ground truth;
// statistics. It edits a ViewerState and draws nothing else.
#pragma once

#include "scene/scene.h"
#include "viewer/viewer_state.h"

namespace mirage {

void drawViewerPanel(const Scene& scene, ViewerState& state);

}  // namespace mirage
