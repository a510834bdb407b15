// The base-colour reflector pass: reflectors shaded with their base colour only (no reflected
// light), through render/shaders/base_colour.frag. The `none` method draws its frame with it,
// and the other methods draw with it the reflectors they do not reflect; one program, so that
// no method names another's shader.
#pragma once

#include "gpu/program.h"

namespace mirage {

// A new program (scene.vert + base_colour.frag) for ScenePasses::drawReflectors and the like.
gpu::Program baseColourProgram();

}  // namespace mirage
