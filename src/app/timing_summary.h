// Frame times summarised as the benchmarks publish them: min, median and 95th percentile
// (interpolated between neighbouring ranks).
#pragma once

#include <vector>

namespace mirage::app {

struct Summary {
  double min = 0, median = 0, p95 = 0;
};

// The summary of `v`; all zero when it is empty.
Summary summarize(std::vector<double> v);

}  // namespace mirage::app
