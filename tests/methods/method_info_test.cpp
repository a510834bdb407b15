// A method's info is its registry entry's, attached by the entry's factory (factoryOf): a method
// made any other way has none, and asking for it is an internal error, not a dangling reference.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "methods/method.h"

namespace mirage {
namespace {

class BareMethod final : public Method {
 public:
  void update(FrameContext&) override {}
  void render(FrameContext&) override {}
};

TEST(MethodInfo, AMethodMadeWithoutItsFactoryHasNone) {
  BareMethod bare;
  try {
    (void)bare.info();
    FAIL() << "info() of a method no factory made";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("internal error: "), std::string::npos) << e.what();
  }
  MethodInfo info;
  info.name = "bare";
  bare.attachInfo(info);
  EXPECT_EQ(&bare.info(), &info);
  EXPECT_EQ(bare.orderRendered(3), 3);  // kAnyOrder: as requested
}

}  // namespace
}  // namespace mirage
