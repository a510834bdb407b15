// advise's choice (app/advise_choice.h): the least summed error within the budget, checked
// against trying every combination, and the report's Pareto fronts.
#include <random>

#include <gtest/gtest.h>

#include "app/advise_choice.h"
#include "app/advise_report.h"

namespace mirage::app {
namespace {

// Every combination of options: the least error within the budget, or -1. Candidate c's
// `fixed` cost is paid once if any reflector takes it (none: no fixed costs). The tests' costs lie
// on the choice's step grid, so that its rounding up does not enter the comparison.
double bruteForce(const std::vector<std::vector<Option>>& options, double budget,
                  const std::vector<double>& fixed = {}) {
  double best = -1.0;
  std::vector<size_t> pick(options.size(), 0);
  while (true) {
    double cost = 0.0, sse = 0.0;
    std::vector<bool> used(fixed.size(), false);
    for (size_t r = 0; r < options.size(); ++r) {
      cost += options[r][pick[r]].cost_ms;
      sse += options[r][pick[r]].sse;
      if (!fixed.empty()) used[pick[r]] = true;
    }
    for (size_t c = 0; c < fixed.size(); ++c) cost += used[c] ? fixed[c] : 0.0;
    if (cost <= budget + 1e-9 && (best < 0.0 || sse < best)) best = sse;
    size_t r = 0;
    while (r < options.size() && ++pick[r] == options[r].size()) pick[r++] = 0;
    if (r == options.size()) return best;
  }
}

TEST(AdviseChoice, LeastErrorWithinTheBudgetAsEveryCombinationSays) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> cost(0.0, 10.0), error(0.0, 100.0);
  int fitted = 0, refused = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::vector<Option>> options(1 + trial % 5);
    for (auto& list : options) {
      list.resize(1 + size_t(trial % 4));
      for (Option& o : list) o = {std::round(cost(random) * 100.0) / 100.0, error(random)};
    }
    const double budget = cost(random) * double(options.size()) * 0.6;
    const double expected = bruteForce(options, budget);
    const std::optional<Choice> got = chooseWithin(options, budget);
    if (expected < 0.0) {
      EXPECT_FALSE(got.has_value()) << trial;
      ++refused;
      continue;
    }
    ASSERT_TRUE(got.has_value()) << trial;
    ++fitted;
    EXPECT_NEAR(got->sse, expected, 1e-9) << trial;
    EXPECT_LE(got->cost_ms, budget + 1e-9) << trial;
    double sse = 0.0;
    for (size_t r = 0; r < options.size(); ++r) sse += options[r][size_t(got->picked[r])].sse;
    EXPECT_NEAR(sse, got->sse, 1e-9);
  }
  EXPECT_GT(fitted, 50);
  EXPECT_GT(refused, 5);
}

TEST(AdviseChoice, FixedCostsArePaidOncePerCandidateUsed) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> cost(0.0, 5.0), error(0.0, 100.0);
  int fitted = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const size_t n = 1 + size_t(trial % 4);
    std::vector<std::vector<Option>> options(1 + size_t(trial % 5), std::vector<Option>(n));
    std::vector<double> fixed(n);
    // Costs on the step grid, so that rounding does not enter the comparison.
    for (double& f : fixed) f = std::round(cost(random) * 100.0) / 100.0;
    for (auto& list : options)
      for (Option& o : list) o = {std::round(cost(random) * 100.0) / 100.0, error(random)};
    const double budget = std::round(cost(random) * double(options.size()) * 100.0) / 100.0;
    const double expected = bruteForce(options, budget, fixed);
    const std::optional<Choice> got = chooseWithFixed(options, fixed, budget, int(n));
    ASSERT_EQ(got.has_value(), expected >= 0.0) << trial;
    if (!got) continue;
    ++fitted;
    EXPECT_NEAR(got->sse, expected, 1e-9) << trial;
    EXPECT_LE(got->cost_ms, budget + 1e-9) << trial;
  }
  EXPECT_GT(fitted, 50);
  // One candidate for both, its overhead paid once, beats splitting them over two.
  const std::vector<std::vector<Option>> two = {{{1, 1}, {1, 0}}, {{1, 0}, {1, 1}}};
  const std::optional<Choice> one = chooseWithFixed(two, {5, 5}, 7.5, 2);
  ASSERT_TRUE(one.has_value());
  EXPECT_EQ(one->picked[0], one->picked[1]);
  EXPECT_DOUBLE_EQ(one->cost_ms, 7.0);
  EXPECT_EQ(chooseWithFixed(two, {5, 5}, 12.0, 2)->sse, 0.0);  // both fit: the best of each
}

TEST(AdviseChoice, CheapestTakesTheLeastCostOfEach) {
  const std::vector<std::vector<Option>> options = {{{3, 1}, {1, 9}}, {{2, 5}, {4, 0}, {0.5, 7}}};
  const Choice c = cheapest(options);
  EXPECT_EQ(c.picked, (std::vector<int>{1, 2}));
  EXPECT_DOUBLE_EQ(c.cost_ms, 1.5);
  EXPECT_FALSE(chooseWithin(options, 1.49).has_value());
  EXPECT_TRUE(chooseWithin(options, 1.5).has_value());
}

TEST(AdviseChoice, TheParetoFrontKeepsWhatNothingBeats) {
  // (ms, sse): the second is beaten by the first (dearer and worse); the fourth is the dearest
  // and the best.
  auto at = [](double ms, double sse) { return Measured{.sse = sse, .part_ms = ms}; };
  const std::vector<Measured> m = {at(10.0, 1.0), at(12.0, 2.0), at(5.0, 1.0), at(1.0, 0.5),
                                   at(0.5, 3.0)};
  EXPECT_EQ(paretoFront(m), (std::vector<int>{4, 3}));
  const std::vector<Measured> n = {at(4.0, 1.0), at(1.0, 0.5), at(2.0, 0.2), at(3.0, 0.1)};
  EXPECT_EQ(paretoFront(n), (std::vector<int>{1, 2, 3}));
}

}  // namespace
}  // namespace mirage::app
