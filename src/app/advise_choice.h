// The choice of `mirage advise` (docs/advise.md): one candidate per reflector, the least summed
// squared error within a frame budget — a multiple-choice knapsack, solved exactly by dynamic
// programming over the cost in steps of `kCostStep` ms (each cost rounded up, so that what is
// chosen fits).
#pragma once

#include <optional>
#include <vector>

namespace mirage::app {

inline constexpr double kCostStep = 0.01;  // ms

struct Option {
  double cost_ms = 0.0;  // what it adds to the frame
  double sse = 0.0;      // summed squared error over the reflector's pixels
};

struct Choice {
  std::vector<int> picked;  // an option per reflector
  double cost_ms = 0.0;     // their summed cost
  double sse = 0.0;         // their summed error
};

// The options, one per reflector, with the least summed error whose summed cost is at most
// `budget_ms`; empty when even the cheapest options exceed it. Every reflector needs one option.
std::optional<Choice> chooseWithin(const std::vector<std::vector<Option>>& options,
                                   double budget_ms);
// The cheapest option of every reflector (what to say when nothing fits). With `fixed_ms`
// (option c of every reflector is candidate c, as for chooseWithFixed), its cost counts the fixed
// cost of each candidate it uses.
Choice cheapest(const std::vector<std::vector<Option>>& options,
                const std::vector<double>& fixed_ms = {});

// The same choice where option c of every reflector is candidate c, and a candidate costs
// `fixed_ms[c]` once if any reflector takes it (an entry's own overhead) besides each
// reflector's `cost_ms`. Exact over the assignments that use at most `max_distinct` candidates:
// for each such set, the multiple-choice knapsack within the budget less the set's fixed costs.
// The choice's cost counts the fixed costs of the candidates it uses.
std::optional<Choice> chooseWithFixed(const std::vector<std::vector<Option>>& options,
                                      const std::vector<double>& fixed_ms, double budget_ms,
                                      int max_distinct);

}  // namespace mirage::app
