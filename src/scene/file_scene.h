// A model file shown as it is: a whole scene from a file (a glTF file with its cameras, say), not
// a model put on the default stage (scene/mesh_stage.h). Its meshes stay where its node
// transforms put them (not fitted), with its materials (mirror materials are the reflectors), its
// cameras, its directional light (else mirage's default light) and the procedural sky. Instances
// are named after their nodes (else their meshes), made unique with -2, -3, ...
//
// Which model files are whole scenes: those with at least one camera, unless --stage says
// otherwise (StageMode in scene/builtin_scenes.h; docs/scene-format.md).
#pragma once

#include <string>

#include "scene/builtin_scenes.h"
#include "scene/model_loader.h"
#include "scene/scene.h"

namespace mirage {

// The scene of `model`, read from `path`. A file without a camera gets one framing it
// (Scene::ensureCamera, logged); one without a reflector is warned about.
Scene makeFileScene(const std::string& path, LoadedModel model);

// The model file at `path` as --scene shows it under `mode`: the default stage or the file as it
// is. InputError naming the file when it is missing or malformed.
Scene loadModelScene(const std::string& path, StageMode mode);

}  // namespace mirage
