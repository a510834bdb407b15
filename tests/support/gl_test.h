// Test fixture for tests that need OpenGL: one headless context per test process. Without an
// OpenGL 4.5 driver the test is skipped, unless MIRAGE_REQUIRE_GL=1 turns the skip into a failure.
#pragma once

#include <gtest/gtest.h>

#include "gpu/context.h"

namespace mirage::test {

// The process's context, or nullptr with the reason in `why`.
gpu::Context* glContext(std::string* why = nullptr);
bool glRequired();

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override;
};

}  // namespace mirage::test
