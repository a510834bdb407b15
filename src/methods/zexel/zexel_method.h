// Method `zexel`: depth-preserving reflection maps (the forward-mapped planar mirror paper,
// §4): each planar mirror keeps a map of colour and distance ("zexels") captured from a
// reference camera behind it looking through it, re-captured only when the scene changes; per
// frame the zexels are forward-warped (McMillan) into the image seen from the eye mirrored in
// the mirror, splatted, and the mirror shows that image. Non-planar reflectors inverse-warp a
// depth-preserving cube map of their surroundings (zexel_curved.h).
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry zexelMethodEntry();

}  // namespace mirage
