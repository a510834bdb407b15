// Method `planar`: exact planar mirrors by re-rendering (the baseline of the forward-mapped
// planar mirror paper, its §2): for every planar reflector facing the eye, the scene is drawn
// again from the eye mirrored in its plane, with the mirror plane as an oblique near plane, into
// an image the mirror then shows pixel for pixel; mirrors seen in a mirror recurse up to the
// reflection order. Reflectors that are not planar show their base colour.
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry planarMethodEntry();

}  // namespace mirage
