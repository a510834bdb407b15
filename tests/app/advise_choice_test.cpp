// advise's choice (app/advise_choice.h): the least summed error within the budget, checked
// against trying every combination, and the report's Pareto fronts.
#include <random>

#include <gtest/gtest.h>

#include "app/advise_choice.h"
#include "app/advise_report.h"

namespace mirage::app {
namespace {

// Every combination of options: the least error within the budget (costs rounded up to the
// step, as the choice does), or -1.
double bruteForce(const std::vector<std::vector<Option>>& options, double budget) {
  double best = -1.0;
  std::vector<size_t> pick(options.size(), 0);
  while (true) {
    double cost = 0.0, sse = 0.0;
    for (size_t r = 0; r < options.size(); ++r) {
      cost += std::ceil(options[r][pick[r]].cost_ms / kCostStep - 1e-9) * kCostStep;
      sse += options[r][pick[r]].sse;
    }
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
