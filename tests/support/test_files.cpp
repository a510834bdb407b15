#include "support/test_files.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace mirage::test {

namespace fs = std::filesystem;

fs::path testTempDir(const std::string& prefix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "-" + info->name();
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  fs::path dir = fs::temp_directory_path() / ("mirage-" + prefix + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ScopedShaderDir::ScopedShaderDir(const std::string& prefix) : dir_(testTempDir(prefix)) {
  ::setenv("MIRAGE_SHADER_DIR", dir_.string().c_str(), 1);
}

ScopedShaderDir::~ScopedShaderDir() { ::unsetenv("MIRAGE_SHADER_DIR"); }

void ScopedShaderDir::write(const std::string& path, const std::string& text) const {
  writeText(dir_ / path, text);
}

void writeText(const fs::path& path, const std::string& text) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::string boxPlyText(vec3 lo, vec3 hi) {
  std::string s =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nelement face 12\nproperty list uchar int vertex_indices\n"
      "end_header\n";
  for (int i = 0; i < 8; ++i)
    s += fmt::format("{} {} {}\n", i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
  for (const char* f : {"0 2 1", "1 2 3", "4 5 6", "5 7 6", "0 1 4", "1 5 4", "2 6 3", "3 6 7",
                        "0 4 2", "2 4 6", "1 3 5", "3 7 5"})
    s += fmt::format("3 {}\n", f);
  return s;
}

CliResult runMirage(const std::string& args, const std::string& env, Fallback fallback,
                    const std::string& redirect) {
  std::string command = env + " " + MIRAGE_BINARY + " " + args + " " + redirect;
  CliResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) r.output.append(buffer.data(), n);
  int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  // The method guard's warning (methods/method_guard.cpp).
  if (fallback == Fallback::kFails && r.output.find("drawing with 'envmap' instead") != std::string::npos)
    ADD_FAILURE() << "mirage " << args << ": a method fell back to envmap, which the test does "
                  << "not expect (a fallback is not a pass):\n" << r.output;
  return r;
}

}  // namespace mirage::test
