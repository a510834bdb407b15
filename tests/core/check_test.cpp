// MIRAGE_CHECK and its comparisons: silent when the invariant holds, and when it does not an
// internal error (exit code 1) naming the file from src/ or tests/ on, the line, the condition and
// both values of a comparison; each operand evaluated once.
#include <gtest/gtest.h>

#include <string>

#include "core/check.h"
#include "core/error.h"

namespace mirage {
namespace {

std::string failureOf(void (*f)()) {
  try {
    f();
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.code(), ExitCode::kFailure);
    return e.what();
  }
  return "";
}

TEST(Check, HoldingInvariantsPassAndEachOperandIsEvaluatedOnce) {
  int calls = 0;
  auto next = [&] { return ++calls; };
  MIRAGE_CHECK(1 + 1 == 2);
  MIRAGE_CHECK_EQ(next(), 1);
  MIRAGE_CHECK_LT(next(), 3);
  MIRAGE_CHECK_GE(next(), 3);
  EXPECT_EQ(calls, 3);
}

TEST(Check, AFailedCheckNamesFileLineAndCondition) {
  const int line = __LINE__ + 1;
  const std::string what = failureOf([] { MIRAGE_CHECK(sizeof(int) == 0); });
  EXPECT_NE(what.find("internal error"), std::string::npos) << what;
  EXPECT_NE(what.find("core/check_test.cpp:" + std::to_string(line) + ":"), std::string::npos)
      << what;
  EXPECT_NE(what.find("sizeof(int) == 0"), std::string::npos) << what;
}

TEST(Check, AFailedComparisonGivesBothValues) {
  const std::string what = failureOf([] {
    const int w = 120, h = 119;
    MIRAGE_CHECK_EQ(w, h);
  });
  EXPECT_NE(what.find("w == h (120 vs. 119)"), std::string::npos) << what;
  const std::string le = failureOf([] { MIRAGE_CHECK_LE(2.5, 1.0); });
  EXPECT_NE(le.find("2.5 <= 1.0 (2.5 vs. 1)"), std::string::npos) << le;
}

}  // namespace
}  // namespace mirage
