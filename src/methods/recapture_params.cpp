#include "methods/recapture_params.h"

namespace mirage {

namespace {

RecapturePolicy policyOf(const ParamValues& params, const char* budget) {
  RecapturePolicy p;
  p.angle_degrees = float(params.real("recapture-angle"));
  p.texels = float(params.real("recapture-texels"));
  p.budget = params.integer(budget);
  return p;
}

}  // namespace

ParamSpec recaptureAngleParam() {
  return ParamSpec::real("recapture-angle", 0.0, 90.0, 1.0,
                         "moving scenes: re-capture a billboard or probe once the direction it "
                         "sees something from has turned by this many degrees (0: any turn)");
}

ParamSpec recaptureTexelsParam() {
  return ParamSpec::real("recapture-texels", 0.0, 1.0e4, 2.0,
                         "moving scenes: re-capture a billboard or probe once what it shows has "
                         "moved or grown by this many of its texels (0: any motion)");
}

ParamSpec billboardBudgetParam() {
  return ParamSpec::integer("billboard-budget", 0, 1 << 20, 16,
                            "moving scenes: billboards re-captured a frame, most drifted first "
                            "(0: every one that drifted beyond the tolerances)");
}

ParamSpec probeBudgetParam() {
  return ParamSpec::integer("probe-budget", 0, 1 << 20, 1,
                            "moving scenes: cube maps (a zexel mirror's maps: one) re-captured "
                            "a frame, most drifted first (0: every one that drifted beyond the "
                            "tolerances)");
}

std::vector<ParamSpec> billboardRecaptureParams() {
  return {recaptureAngleParam(), recaptureTexelsParam(), billboardBudgetParam()};
}

std::vector<ParamSpec> probeRecaptureParams() {
  return {recaptureAngleParam(), recaptureTexelsParam(), probeBudgetParam()};
}

RecapturePolicy billboardRecapture(const ParamValues& params) {
  return policyOf(params, "billboard-budget");
}

RecapturePolicy probeRecapture(const ParamValues& params) {
  return policyOf(params, "probe-budget");
}

}  // namespace mirage
