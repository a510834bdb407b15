#include "app/timing_summary.h"

#include <algorithm>

namespace mirage::app {

Summary summarize(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  auto at = [&](double q) {
    double pos = q * double(v.size() - 1);
    size_t i = size_t(pos);
    double f = pos - double(i);
    return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
  };
  return {v.front(), at(0.5), at(0.95)};
}

}  // namespace mirage::app
