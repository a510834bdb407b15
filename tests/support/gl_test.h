// Test fixture for tests that need OpenGL: one headless context per test process. Without an
// OpenGL 4.5 driver the test is skipped, unless MIRAGE_REQUIRE_GL=1 turns the skip into a failure.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>

#include "gpu/context.h"

namespace mirage::test {

// The process's context, or nullptr with the reason in `why`.
gpu::Context* glContext(std::string* why = nullptr);
bool glRequired();

// An X display is set (DISPLAY): the window tests need one; ctest runs them under xvfb-run.
bool haveDisplay();

// In a window test: without a display, fails when MIRAGE_REQUIRE_DISPLAY is set (ctest's Xvfb
// runs) and skips otherwise.
#define MIRAGE_NEED_DISPLAY()                                                                \
  do {                                                                                       \
    if (!::mirage::test::haveDisplay()) {                                                    \
      if (std::getenv("MIRAGE_REQUIRE_DISPLAY")) FAIL() << "no DISPLAY: run under xvfb-run"; \
      GTEST_SKIP() << "no DISPLAY (ctest runs this under xvfb-run)";                         \
    }                                                                                        \
  } while (false)

// A GL test fails where a method fell back to envmap (methods/method_guard.h) unless it said it
// expects that (expectFallback()): a test whose method fell back has not tested that method.
class GlTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  void expectFallback() { fallback_expected_ = true; }

 private:
  long long fallbacks_at_start_ = 0;
  bool fallback_expected_ = false;
};

}  // namespace mirage::test
