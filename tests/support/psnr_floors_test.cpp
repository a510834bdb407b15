// The table of PSNR floors keeps its own promise: every floor lies at or below what was measured
// when it was set, no more than kFloorMargin below it without a stated reason, and every name
// (the tag of a failure's images) is used once. scripts/psnr-floors --check (ctest) holds the
// tests to the table.
#include <gtest/gtest.h>

#include <iterator>
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
    if (!f->reason) {
      EXPECT_LE(f->measured - f->floor, kFloorMargin)
          << f->name << ": more than " << kFloorMargin << " dB below its measurement, no reason";
    }
    EXPECT_TRUE(names.insert(f->name).second) << f->name << " twice";
  }
  EXPECT_EQ(names.size(), std::size(floors::kAll));
}

}  // namespace
}  // namespace mirage::test
