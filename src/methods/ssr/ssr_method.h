// Method `ssr`: screen-space reflections as today's engines render mirrors — a G-buffer of the
// direct view (depth, normal, material, colour), a screen-space pass over its reflector pixels:
// a hierarchical-Z march of each reflected
// ray through its depth with a thickness test and a binary refinement, the colour of the hit
// pixel, a fade where the screen's data ends, and a reflection probe (`envmap` or `envmap-box`,
// --ssr-fallback) wherever the screen has no answer. Order 1 only.
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry ssrMethodEntry();

}  // namespace mirage
