// Method `mixed`: each reflector drawn by the method an assignment gives it (methods/assignment.h,
// docs/advise.md). The direct part of the eye view is drawn once; then each assigned method draws
// its own reflectors (FrameContext::own) over it, with its own parameters and order, keeping its
// own rule for the reflectors seen within its bounces and captures. An assignment that gives
// every reflector one method draws that method's frame bit for bit.
#pragma once

#include <span>

#include "methods/method.h"

namespace mirage {

// `methods`: every method it may assign (the rest of the registry), whose parameters it takes
// too, as defaults for every entry.
MethodEntry mixedMethodEntry(std::span<const MethodEntry> methods);

}  // namespace mirage
