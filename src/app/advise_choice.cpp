#include "app/advise_choice.h"

#include <cmath>
#include <functional>
#include <limits>

#include "core/check.h"

namespace mirage::app {

namespace {

int steps(double ms) {
  return int(std::ceil(std::max(ms, 0.0) / kCostStep - 1e-9));
}

Choice summed(const std::vector<std::vector<Option>>& options, std::vector<int> picked) {
  Choice c{std::move(picked), 0.0, 0.0};
  for (size_t r = 0; r < options.size(); ++r) {
    c.cost_ms += options[r][size_t(c.picked[r])].cost_ms;
    c.sse += options[r][size_t(c.picked[r])].sse;
  }
  return c;
}

// The fixed costs of the candidates `picked` uses, each once.
double fixedOfUsed(const std::vector<int>& picked, const std::vector<double>& fixed_ms) {
  std::vector<bool> used(fixed_ms.size(), false);
  double out = 0.0;
  for (int c : picked) {
    if (used[size_t(c)]) continue;
    used[size_t(c)] = true;
    out += fixed_ms[size_t(c)];
  }
  return out;
}

}  // namespace

std::optional<Choice> chooseWithin(const std::vector<std::vector<Option>>& options,
                                   double budget_ms) {
  if (budget_ms < 0.0) return std::nullopt;
  const int capacity = int(std::floor(budget_ms / kCostStep + 1e-9));
  constexpr double kNone = std::numeric_limits<double>::infinity();
  // best[r][c]: the least error of reflectors 0..r-1 within c steps; from[r][c] its option.
  std::vector<std::vector<double>> best(options.size() + 1,
                                        std::vector<double>(size_t(capacity) + 1, kNone));
  std::vector<std::vector<int>> from(options.size(), std::vector<int>(size_t(capacity) + 1, -1));
  std::fill(best[0].begin(), best[0].end(), 0.0);
  for (size_t r = 0; r < options.size(); ++r) {
    MIRAGE_CHECK(!options[r].empty());
    for (int c = 0; c <= capacity; ++c)
      for (size_t o = 0; o < options[r].size(); ++o) {
        const int s = steps(options[r][o].cost_ms);
        if (s > c || best[r][size_t(c - s)] == kNone) continue;
        const double e = best[r][size_t(c - s)] + options[r][o].sse;
        if (e < best[r + 1][size_t(c)]) {
          best[r + 1][size_t(c)] = e;
          from[r][size_t(c)] = int(o);
        }
      }
  }
  if (best.back()[size_t(capacity)] == kNone) return std::nullopt;
  std::vector<int> picked(options.size());
  int c = capacity;
  for (size_t r = options.size(); r-- > 0;) {
    picked[r] = from[r][size_t(c)];
    c -= steps(options[r][size_t(picked[r])].cost_ms);
  }
  return summed(options, std::move(picked));
}

Choice cheapest(const std::vector<std::vector<Option>>& options,
                const std::vector<double>& fixed_ms) {
  std::vector<int> picked;
  for (const auto& list : options) {
    MIRAGE_CHECK(!list.empty());
    int k = 0;
    for (size_t o = 1; o < list.size(); ++o)
      if (list[o].cost_ms < list[size_t(k)].cost_ms) k = int(o);
    picked.push_back(k);
  }
  Choice c = summed(options, std::move(picked));
  if (!fixed_ms.empty()) c.cost_ms += fixedOfUsed(c.picked, fixed_ms);
  return c;
}

namespace {

// Calls `visit` with every set of at most `k` of the indices 0..n-1 (as a list, ascending).
void subsets(int n, int k, std::vector<int>& set, int from,
             const std::function<void(const std::vector<int>&)>& visit) {
  if (!set.empty()) visit(set);
  if (int(set.size()) == k) return;
  for (int i = from; i < n; ++i) {
    set.push_back(i);
    subsets(n, k, set, i + 1, visit);
    set.pop_back();
  }
}

}  // namespace

std::optional<Choice> chooseWithFixed(const std::vector<std::vector<Option>>& options,
                                      const std::vector<double>& fixed_ms, double budget_ms,
                                      int max_distinct) {
  const int n = int(fixed_ms.size());
  for (const auto& list : options) MIRAGE_CHECK(int(list.size()) == n);
  std::optional<Choice> best;
  std::vector<int> set;
  subsets(n, max_distinct, set, 0, [&](const std::vector<int>& u) {
    double fixed = 0.0;
    for (int c : u) fixed += fixed_ms[size_t(c)];
    std::vector<std::vector<Option>> restricted(options.size());
    for (size_t r = 0; r < options.size(); ++r)
      for (int c : u) restricted[r].push_back(options[r][size_t(c)]);
    std::optional<Choice> within = chooseWithin(restricted, budget_ms - fixed);
    if (!within) return;
    std::vector<int> picked;
    for (int k : within->picked) picked.push_back(u[size_t(k)]);
    Choice choice = summed(options, std::move(picked));
    choice.cost_ms += fixedOfUsed(choice.picked, fixed_ms);
    if (!best || choice.sse < best->sse ||
        (choice.sse == best->sse && choice.cost_ms < best->cost_ms))
      best = std::move(choice);
  });
  return best;
}

}  // namespace mirage::app
