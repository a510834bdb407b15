// Uniform names checked (gpu/program.h): with the checks on, as the tests' main has them, a set()
// of a name the program's sources do not declare throws naming the program and the name; a
// declared uniform the compiler removed stays a no-op; the declarations are read from the GLSL
// text as the grammar has them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "gpu/program.h"
#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::gpu {
namespace {

using Names = std::vector<std::string>;

TEST(DeclaredUniforms, ReadsDeclaratorsAfterQualifiersAndSkipsBlocksAndComments) {
  EXPECT_EQ(declaredUniforms("uniform float u_a;\nuniform highp vec3 u_b , u_c[4];"),
            (Names{"u_a", "u_b", "u_c"}));
  EXPECT_EQ(declaredUniforms("layout(binding = 2) uniform sampler2D u_tex;"), Names{"u_tex"});
  EXPECT_EQ(declaredUniforms("layout(rgba32f) uniform coherent restrict image2D u_img;"),
            Names{"u_img"});
  EXPECT_EQ(declaredUniforms("uniform int u_n = 3, u_m;"), (Names{"u_n", "u_m"}));
  EXPECT_EQ(declaredUniforms("layout(std140) uniform Block { FrameData frame; };"), Names{});
  EXPECT_EQ(declaredUniforms("// uniform float u_commented;\n/* uniform int u_block; */"),
            Names{});
  EXPECT_EQ(declaredUniforms("float uniformity; uniforms u_x;"), Names{});
}

class UniformChecks : public test::GlTest {};

constexpr const char* kCompute = R"(layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { float out_value[]; };
uniform float u_used;
uniform float u_unused;  // declared, never read: the compiler removes it
uniform int u_a, u_b[2];
void main() { out_value[0] = u_used + float(u_a); }
)";

TEST_F(UniformChecks, AnUndeclaredNameThrowsADeclaredInactiveOneDoesNot) {
  ASSERT_TRUE(uniformChecks()) << "the tests' main turns the checks on";
  test::ScopedShaderDir dir("uniform-checks");
  dir.write("render/shaders/fullscreen.vert", kCompute);  // any embedded path serves
  const Program program = Program::compute("render/shaders/fullscreen.vert");
  EXPECT_NO_THROW(program.set("u_used", 1.0f));
  EXPECT_NO_THROW(program.set("u_a", 2));
  EXPECT_LT(program.location("u_unused"), 0);
  EXPECT_NO_THROW(program.set("u_unused", 1.0f));
  EXPECT_NO_THROW(program.set("u_b[1]", 1));
  try {
    program.set("u_usde", 1.0f);
    FAIL() << "a misspelt uniform was set silently";
  } catch (const RuntimeError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'u_usde'"), std::string::npos) << what;
    EXPECT_NE(what.find("render/shaders/fullscreen.vert"), std::string::npos) << what;
  }
  setUniformChecks(false);
  EXPECT_NO_THROW(program.set("u_usde", 1.0f));
  setUniformChecks(true);
}

}  // namespace
}  // namespace mirage::gpu
