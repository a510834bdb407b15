// The fuzz corpus replayed in every test run: each seed and each regression input of a crash the
// fuzzers found (tests/fuzz/corpus/<target>/) goes through the parser its target drives
// (fuzz/fuzz_inputs.h) and must end in success or an InputError naming the input — never another
// exception, a sanitizer report (the asan preset) or a hang (each well within a second here).
#include <chrono>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "fuzz/fuzz_inputs.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

TEST(FuzzCorpus, EveryInputParsesOrIsAnInputError) {
  int total = 0;
  for (const fuzz::Target& target : fuzz::kTargets) {
    const fs::path folder = fs::path(MIRAGE_FUZZ_CORPUS) / target.name;
    ASSERT_TRUE(fs::is_directory(folder)) << folder;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string bytes = readFile(entry.path().string());
      const auto start = std::chrono::steady_clock::now();
      try {
        target.parse(bytes);
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fuzz"), std::string::npos)
            << entry.path() << ": the message names no input: " << e.what();
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": " << typeid(e).name() << ": " << e.what();
      }
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_LT(s, 5.0) << entry.path();
      ++files;
    }
    EXPECT_GT(files, 0) << target.name;
    total += files;
  }
  std::printf("replayed %d corpus inputs\n", total);
}

}  // namespace
}  // namespace mirage::test
