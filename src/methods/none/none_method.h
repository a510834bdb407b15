// `none`: reflectors shaded with their base colour only. The no-mirror frame that every cost is
// compared with (ratio_to_none in benchmarks).
#pragma once

#include "methods/method.h"

namespace mirage {

MethodEntry noneMethodEntry();

}  // namespace mirage
