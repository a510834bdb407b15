#include "support/image_check.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "eval/heatmap.h"

namespace mirage::test {

std::string writeArtifacts(const Image& actual, const Image& expected, const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? fmt::format("{}.{}", info->test_suite_name(), info->name()) : "test";
  std::filesystem::path dir = std::filesystem::path(MIRAGE_TEST_ARTIFACTS) / name;
  std::filesystem::create_directories(dir);
  writePng((dir / (tag + ".actual.png")).string(), actual);
  writePng((dir / (tag + ".expected.png")).string(), expected);
  writePng((dir / (tag + ".diff.png")).string(), heatmap(absoluteError(actual, expected), 0.25f));
  return dir.string();
}

namespace {

// One line per floor check in $MIRAGE_PSNR_LOG: test, floor, measured, floor dB, measured here.
void logFloor(double psnr, const PsnrFloor& floor) {
  const char* path = std::getenv("MIRAGE_PSNR_LOG");
  if (!path || !*path) return;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::ofstream out(path, std::ios::app);
  out << (info ? fmt::format("{}.{}", info->test_suite_name(), info->name()) : "test") << '\t'
      << floor.name << '\t'
      << fmt::format("{:.2f}\t{:.2f}\t{:.2f}", psnr, floor.floor, floor.measured) << '\n';
}

}  // namespace

::testing::AssertionResult meetsFloor(double psnr, const PsnrFloor& floor) {
  logFloor(psnr, floor);
  if (psnr >= floor.floor)
    return ::testing::AssertionSuccess() << floor.name << ": PSNR " << psnr << " dB";
  return ::testing::AssertionFailure()
         << floor.name << ": PSNR " << psnr << " dB < its floor " << floor.floor << " dB (measured "
         << floor.measured << " dB on the platform of support/psnr_floors.h)";
}

::testing::AssertionResult psnrAtLeast(const Image& actual, const Image& expected,
                                       const PsnrFloor& floor, const IdImage* mask,
                                       const std::string& tag) {
  const double psnr = psnrFromMse(meanSquaredError(actual, expected, mask));
  ::testing::AssertionResult result = meetsFloor(psnr, floor);
  if (!result)
    result << "; images in " << writeArtifacts(actual, expected, tag.empty() ? floor.name : tag);
  return result;
}

::testing::AssertionResult imagesEqual(const Image& actual, const Image& expected,
                                       float max_difference, const IdImage* mask,
                                       const std::string& tag) {
  if (actual.width() != expected.width() || actual.height() != expected.height())
    return ::testing::AssertionFailure() << tag << ": sizes " << actual.width() << "x"
                                         << actual.height() << " and " << expected.width() << "x"
                                         << expected.height();
  size_t off = 0, worst_at = 0;
  float worst = 0.0f;
  for (size_t i = 0; i < actual.pixelCount(); ++i) {
    if (mask && mask->data()[i] == 0) continue;
    const vec3 d = glm::abs(vec3(actual.data()[i]) - vec3(expected.data()[i]));
    const float m = std::max({d.x, d.y, d.z});
    if (!(m <= max_difference)) ++off;
    if (!(m <= worst)) {
      worst = m;
      worst_at = i;
    }
  }
  if (off == 0)
    return ::testing::AssertionSuccess() << "largest difference " << worst;
  return ::testing::AssertionFailure()
         << tag << ": " << off << " pixels differ by more than " << max_difference
         << ", the most " << worst << " at (" << worst_at % size_t(actual.width()) << ", "
         << worst_at / size_t(actual.width()) << "); images in "
         << writeArtifacts(actual, expected, tag);
}

::testing::AssertionResult mostPixelsWithin(const Image& actual, const Image& expected,
                                            float tolerance, double max_fraction,
                                            const IdImage* mask, const std::string& tag) {
  size_t bad = 0, total = 0;
  for (size_t i = 0; i < actual.pixelCount(); ++i) {
    if (mask && mask->data()[i] == 0) continue;
    ++total;
    vec3 d = glm::abs(vec3(actual.data()[i]) - vec3(expected.data()[i]));
    if (std::max({d.x, d.y, d.z}) > tolerance) ++bad;
  }
  double fraction = total ? double(bad) / double(total) : 0.0;
  if (fraction <= max_fraction)
    return ::testing::AssertionSuccess() << bad << " of " << total << " pixels off";
  return ::testing::AssertionFailure()
         << tag << ": " << bad << " of " << total << " pixels (" << fraction * 100.0
         << "%) differ by more than " << tolerance << " (allowed " << max_fraction * 100.0
         << "%); images in " << writeArtifacts(actual, expected, tag);
}

std::vector<bool> changedPixels(const Image& a, const Image& b) {
  std::vector<bool> changed(a.pixelCount());
  for (size_t i = 0; i < changed.size(); ++i)
    changed[i] =
        glm::any(glm::greaterThan(glm::abs(vec3(a.data()[i]) - vec3(b.data()[i])), vec3(1e-5f)));
  return changed;
}

}  // namespace mirage::test
