// The shader loader without a GL context: #include resolved textually (relative to the including
// file, then to src/), each file once, every file's lines renumbered by #line so that a driver's
// log can be turned back into file:line (annotateShaderLog). The expected texts are written out
// here from the rules, not produced by the loader's own helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "gpu/shader_source.h"
#include "support/test_files.h"

namespace mirage::gpu {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(ShaderSource, VersionAndDefinesComeFirst) {
  const ShaderSource s = loadShaderSource("render/shaders/fullscreen.vert", {"A", "B 2"});
  const std::vector<std::string> lines = linesOf(s.text);
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[0], "#version 450 core");
  EXPECT_EQ(lines[1], "#define MIRAGE_GLSL 1");
  EXPECT_EQ(lines[2], "#define A");
  EXPECT_EQ(lines[3], "#define B 2");
  EXPECT_EQ(lines[4], "#line 1 0");
  EXPECT_EQ(s.files.front(), "render/shaders/fullscreen.vert");
}

// base_colour.frag -> reflector.glsl -> surface.glsl -> common.glsl -> {gpu_types.h, shading.h},
// and shading.h includes gpu_types.h again: it must appear once, and each file's number is its
// index in `files`.
TEST(ShaderSource, IncludesAreExpandedOnceEachWithTheirOwnLineNumbers) {
  const ShaderSource s = loadShaderSource("render/shaders/base_colour.frag");
  const std::vector<std::string>& f = s.files;
  for (const char* path : {"render/shaders/base_colour.frag", "render/shaders/reflector.glsl",
                           "render/shaders/surface.glsl", "render/shaders/common.glsl",
                           "shading/gpu_types.h", "shading/shading.h"})
    EXPECT_EQ(std::count(f.begin(), f.end(), path), 1) << path;
  const std::vector<std::string> lines = linesOf(s.text);
  for (size_t i = 0; i < f.size(); ++i)
    EXPECT_EQ(std::count(lines.begin(), lines.end(), "#line 1 " + std::to_string(i)), 1) << f[i];
  // After the include on line L of file 0, numbering resumes at L + 1 in file 0.
  const std::vector<std::string> own = linesOf(shaderFile("render/shaders/base_colour.frag"));
  auto include = std::find_if(own.begin(), own.end(),
                              [](const std::string& l) { return l.rfind("#include", 0) == 0; });
  ASSERT_NE(include, own.end());
  const std::string resume = "#line " + std::to_string(include - own.begin() + 2) + " 0";
  EXPECT_NE(std::find(lines.begin(), lines.end(), resume), lines.end()) << resume;
  EXPECT_EQ(s.text.find("#include \""), std::string::npos);
}

TEST(ShaderSource, RelativeIncludesThenFromSrcAndAngleIncludesDropped) {
  test::ScopedShaderDir dir("shader-source");
  // A file at an embedded path, replaced by the test's: "common.glsl" resolves next to it
  // (render/shaders/common.glsl), "shading/glsl_compat.h" from src/, <cmath> is C++ only.
  dir.write("render/shaders/fullscreen.vert",
            "// first\n#include \"common.glsl\"\n#include <cmath>\n"
            "  #include \"shading/glsl_compat.h\"\nvoid main() {}\n");
  const ShaderSource s = loadShaderSource("render/shaders/fullscreen.vert");
  ASSERT_GE(s.files.size(), 2u);
  EXPECT_EQ(s.files[0], "render/shaders/fullscreen.vert");
  EXPECT_EQ(s.files[1], "render/shaders/common.glsl");
  EXPECT_NE(std::find(s.files.begin(), s.files.end(), "shading/glsl_compat.h"), s.files.end());
  const std::vector<std::string> lines = linesOf(s.text);
  EXPECT_NE(std::find(lines.begin(), lines.end(), "#line 3 0"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "#line 5 0"), lines.end());
  EXPECT_EQ(lines.back(), "void main() {}");
  EXPECT_EQ(s.text.find("cmath"), std::string::npos);
}

TEST(ShaderSource, AMissingIncludeNamesTheFileAndLine) {
  test::ScopedShaderDir dir("shader-source-missing");
  dir.write("render/shaders/fullscreen.vert", "\n\n#include \"no/such/file.glsl\"\n");
  try {
    loadShaderSource("render/shaders/fullscreen.vert");
    FAIL() << "a missing include was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("render/shaders/fullscreen.vert:3:"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("no/such/file.glsl"), std::string::npos) << e.what();
  }
  dir.write("render/shaders/fullscreen.vert", "#include \"unclosed\n");
  EXPECT_THROW(loadShaderSource("render/shaders/fullscreen.vert"), Error);
}

TEST(ShaderSource, UnknownFileIsAnError) {
  EXPECT_THROW(shaderFile("render/shaders/no_such_shader.frag"), Error);
}

TEST(ShaderLog, LocationsOfMesaAndNvidiaLogsNameTheFile) {
  const std::vector<std::string> files = {"a.frag", "b.glsl"};
  EXPECT_EQ(annotateShaderLog("0:12(5): error: `x' undeclared\n", files),
            "a.frag:12: error: `x' undeclared\n");
  EXPECT_EQ(annotateShaderLog("1(7) : error C1008: undefined variable\n", files),
            "b.glsl:7 : error C1008: undefined variable\n");
  // A file number beyond the list and a line without a location stay as they were.
  EXPECT_EQ(annotateShaderLog("5:3(1): warning: w\nlinker: failed\n", files),
            "5:3(1): warning: w\nlinker: failed\n");
}

}  // namespace
}  // namespace mirage::gpu
