// `raytrace`: the Embree ground truth behind the method interface, so that reports, benchmarks
// and the viewer treat it like any method. Renders on the CPU and uploads into the frame target.
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry raytraceMethodEntry();

}  // namespace mirage
