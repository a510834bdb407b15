#include "support/gl_test.h"

#include <cstdlib>
#include <cstring>
#include <memory>

#include "core/error.h"

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
  std::string why;
  if (glContext(&why)) return;
  if (glRequired())
    FAIL() << "MIRAGE_REQUIRE_GL is set but there is no OpenGL 4.5 context: " << why;
  GTEST_SKIP() << "no OpenGL 4.5 driver: " << why;
}

bool haveDisplay() {
  const char* d = std::getenv("DISPLAY");
  return d && *d;
}

}  // namespace mirage::test
