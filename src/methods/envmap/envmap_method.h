// Environment-mapped reflections, the baselines of the papers:
//  - `envmap`: a cube map captured at each reflector's centre (traditional reflection mapping,
//    what engines call a dynamic reflection probe), re-captured only when the scene changes;
//    order K by K capture passes in which the other reflectors show the previous pass's probes;
//  - `envmap-box`: the same probes looked up through a box proxy of the room (Bjorke's proxy
//    made a box, as the impostor paper suggests; engines call it a parallax-corrected cube map);
//  - `envmap-infinite`: the scene's distant environment only (a light probe at infinity).
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry envmapMethodEntry();
MethodEntry envmapBoxMethodEntry();
MethodEntry envmapInfiniteMethodEntry();

}  // namespace mirage
