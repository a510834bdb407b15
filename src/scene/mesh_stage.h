// The default stage for a bare mesh or model file (`mirage render --scene bunny.ply`): the model
// fitted to about 2 units and standing on a checkerboard ground among a few coloured boxes, under
// the procedural sky, seen from the front-left and above. A model without materials of its own is
// mirror-finished; one whose materials hold no reflector gets a mirror sphere beside it, so that
// every stage shows reflections of the model.
#pragma once

#include <string>

#include "scene/scene.h"

namespace mirage {

// Size of the model's largest extent on the stage, in scene units.
inline constexpr float kStageModelSize = 2.0f;

// Builds the stage around the model file at `path`; throws InputError naming the file when it
// is missing or malformed.
Scene makeMeshStage(const std::string& path);

}  // namespace mirage
