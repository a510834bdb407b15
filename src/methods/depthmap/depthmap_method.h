// `depthmap`: reflected-scene impostors with depth maps (the impostor paper, §4): every
// non-planar diffuse object is reflected through its depth maps, searched per ray through
// simplified rotated depth maps (SRDMs), or by a brute-force walk of the full map; the ground,
// planar objects and the other reflectors stay billboards, a miss gives the environment.
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry depthmapMethodEntry();

}  // namespace mirage
