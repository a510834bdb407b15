// `billboard`: reflected-scene impostors made of billboards (the impostor paper, §3; the order-K
// pixel algorithm of its slides). Diffuse billboards per (object, reflector), planar objects as
// their own billboards, reflective billboards per (reflector, other reflector), the environment
// without the billboarded objects on a miss.
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry billboardMethodEntry();

}  // namespace mirage
