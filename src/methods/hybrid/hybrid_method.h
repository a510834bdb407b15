// `hybrid`: the hybrid backward-forward method (Mei, Popescu, Sacks): the non-planar diffuse
// objects as point samples in kd-trees; per frame a continuous 3-ray camera (C3RC) per visible
// reflector triangle, its view volume culled against the kd-trees on the CPU (backward), the
// points of the surviving leaves projected through it and splatted by a compute shader
// (forward), over a cube map of the rest of the scene.
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry hybridMethodEntry();

}  // namespace mirage
