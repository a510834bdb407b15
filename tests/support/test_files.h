// Files and processes the tests share: a fresh folder per test, text files, a small PLY mesh,
// and running the `mirage` executable with its exit code and output.
#pragma once

#include <filesystem>
#include <string>

#include "core/math.h"

namespace mirage::test {

// A fresh, empty folder for the running test, <tmp>/mirage-<prefix>-<suite>-<test>: one per
// test, since ctest runs the cases (of a parameterised test too) in parallel.
std::filesystem::path testTempDir(const std::string& prefix);

// Writes `text` to `path` (binary), creating the parent folders.
void writeText(const std::filesystem::path& path, const std::string& text);

// MIRAGE_SHADER_DIR pointed at a fresh folder of the test's own shader files for one scope: a
// file written there replaces the embedded file of the same path (as for live editing).
class ScopedShaderDir {
 public:
  explicit ScopedShaderDir(const std::string& prefix);
  ~ScopedShaderDir();
  ScopedShaderDir(const ScopedShaderDir&) = delete;
  ScopedShaderDir& operator=(const ScopedShaderDir&) = delete;
  void write(const std::string& path, const std::string& text) const;

 private:
  std::filesystem::path dir_;
};

// An ASCII PLY of the axis-aligned box from `lo` to `hi` (8 vertices, 12 triangles).
std::string boxPlyText(vec3 lo = vec3(0.0f), vec3 hi = vec3(1.0f));

struct CliResult {
  int code = -1;  // the exit code (-1: not started, or killed by a signal)
  std::string output;
};

// Whether a run of the tool may fall back from a method to envmap (methods/method_guard.h).
enum class Fallback { kFails, kExpected };
inline constexpr Fallback kFallbackExpected = Fallback::kExpected;

// Runs the `mirage` executable of this build with `args`. `env` is prefixed (variable
// assignments); `redirect` decides which streams are captured ("2>&1": both, "2>/dev/null":
// stdout only, "2>&1 >/dev/null": stderr only). Where the output shows that a method fell back
// to envmap, the test fails unless `fallback` expects it: a fallback is not a pass.
CliResult runMirage(const std::string& args, const std::string& env = "",
                    Fallback fallback = Fallback::kFails, const std::string& redirect = "2>&1");

}  // namespace mirage::test
