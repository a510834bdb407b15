// The default stage for a bare mesh or model file (`mirage render --scene bunny.ply`): the model
// fitted to about 2 units and standing on a checkerboard ground among a few coloured boxes, under
// the procedural sky, seen from the front-left and above. A model without materials of its own is
// mirror-finished; one whose materials hold no reflector gets a mirror sphere beside it, so that
// every stage shows reflections of the model. (A file with a camera of its own is shown as it is
// instead, unless --stage on: scene/file_scene.h.)
#pragma once

#include <string>

#include "scene/model_loader.h"
#include "scene/scene.h"

namespace mirage {

// Size of the model's largest extent on the stage, in scene units.
inline constexpr float kStageModelSize = 2.0f;

// The model file at `path` as --scene reads it; throws InputError naming the file when it is
// missing, a folder or malformed.
LoadedModel loadSceneModel(const std::string& path);

// Builds the stage around the model file at `path` (loadSceneModel, then the stage).
Scene makeMeshStage(const std::string& path);
// The stage around `model`, read from `path`. The file's own cameras follow the stage's camera
// "main", moved with the model by the stage's fit (--camera finds them on the stage too).
Scene makeMeshStage(const std::string& path, LoadedModel model);

}  // namespace mirage
