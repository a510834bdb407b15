// The parameters of amortised re-capture in moving scenes (render/recapture.h), one spec each so
// that every method listing them shares a range, a default and a help text: the tolerances are
// common to billboards and probes; the budgets count different work (a billboard is one object
// drawn once, a probe the whole scene drawn six times), so each kind has its own.
#pragma once

#include "methods/params.h"
#include "render/recapture.h"

namespace mirage {

// --recapture-angle DEG and --recapture-texels N: the drift tolerances.
ParamSpec recaptureAngleParam();
ParamSpec recaptureTexelsParam();
// --billboard-budget N: billboards re-captured a frame (0: all that drifted).
ParamSpec billboardBudgetParam();
// --probe-budget N: cube maps re-captured a frame (0: all that drifted).
ParamSpec probeBudgetParam();

// The three parameters of billboards (impostor methods) and of probes, in the order listed.
std::vector<ParamSpec> billboardRecaptureParams();
std::vector<ParamSpec> probeRecaptureParams();

RecapturePolicy billboardRecapture(const ParamValues& params);
RecapturePolicy probeRecapture(const ParamValues& params);

}  // namespace mirage
