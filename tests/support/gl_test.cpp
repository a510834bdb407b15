#include "support/gl_test.h"

#include <cstdlib>
#include <cstring>
#include <memory>

#include "core/error.h"
#include "methods/method_guard.h"

namespace mirage::test {

gpu::Context* glContext(std::string* why) {
  static std::string reason;
  static std::unique_ptr<gpu::Context> context = [] {
    try {
      return gpu::createHeadlessContext({gpu::debugContextByDefault()});
    } catch (const Error& e) {
      reason = e.what();
      return std::unique_ptr<gpu::Context>();
    }
  }();
  if (why) *why = reason;
  return context.get();
}

bool glRequired() {
  const char* env = std::getenv("MIRAGE_REQUIRE_GL");
  return env && std::strcmp(env, "0") != 0;
}

void GlTest::SetUp() {
  fallbacks_at_start_ = methodFallbacks();
  std::string why;
  if (glContext(&why)) return;
  if (glRequired())
    FAIL() << "MIRAGE_REQUIRE_GL is set but there is no OpenGL 4.5 context: " << why;
  GTEST_SKIP() << "no OpenGL 4.5 driver: " << why;
}

void GlTest::TearDown() {
  const long long fell = methodFallbacks() - fallbacks_at_start_;
  if (fell > 0 && !fallback_expected_)
    ADD_FAILURE() << fell << " method(s) fell back to envmap in this test (the warning above says "
                  << "why), which it does not expect: a fallback is not a pass";
}

bool haveDisplay() {
  const char* d = std::getenv("DISPLAY");
  return d && *d;
}

}  // namespace mirage::test
