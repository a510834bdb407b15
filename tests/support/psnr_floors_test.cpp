// The table of PSNR floors keeps its own promise: every floor lies at or below what was measured
// when it was set, and every name (the tag of a failure's images) is used once.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "support/psnr_floors.h"

namespace mirage::test {
namespace {

TEST(PsnrFloors, EachFloorIsAtMostItsMeasurementAndNamedOnce) {
  std::set<std::string> names;
  for (const PsnrFloor* f : floors::kAll) {
    EXPECT_LE(f->floor, f->measured) << f->name;
    EXPECT_GT(f->floor, 0.0) << f->name;
    EXPECT_TRUE(names.insert(f->name).second) << f->name << " twice";
  }
  EXPECT_EQ(names.size(), 26u);
}

}  // namespace
}  // namespace mirage::test
