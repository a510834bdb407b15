// A method the driver refuses (GpuError: a limit) hands the frame to envmap with a warning: made,
// updated or drawn, the frame is envmap's own, never black or half drawn; envmap refused too is an
// error. A shader of ours that does not compile (ShaderError) is no driver limit: an error.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/image.h"
#include "methods/frame.h"
#include "methods/method_guard.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

class MethodGuardTest : public GlTest {};

enum class FailIn { kNothing, kUpdate, kRender };

// Stands for a method whose shaders or textures the driver refuses at one point of the frame.
// Before refusing in render() it paints the frame, as a method that fails half-way would.
class RefusedMethod : public Method {
 public:
  explicit RefusedMethod(FailIn when) : when_(when) {}
  const MethodInfo& info() const override {
    static const MethodInfo info = [] {
      MethodInfo i;
      i.name = "refused";
      i.description = "fails on purpose";
      return i;
    }();
    return info;
  }
  void update(FrameContext&) override {
    if (when_ == FailIn::kUpdate) throwGpu("texture size 99999x99999 is beyond the test's limit");
  }
  void render(FrameContext&) override {
    glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (when_ == FailIn::kRender) throwGpu("a storage block of 3 GiB is beyond the test's limit");
  }

 private:
  FailIn when_;
};

constexpr ivec2 kSize{64, 48};

Image renderWith(FrameRenderer& renderer, Method& method, const Scene& scene) {
  FrameSettings settings;
  renderer.render(method, View(scene.camera(), kSize), 0.0f, settings);
  return renderer.read().color;
}

size_t differingPixels(const Image& a, const Image& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.pixelCount(); ++i) n += a.data()[i] != b.data()[i] ? 1u : 0u;
  return n;
}

TEST_F(MethodGuardTest, RefusedWhenMadeUpdatedOrDrawnTheFrameIsEnvmaps) {
  expectFallback();
  const Scene scene = makeBuiltinScene("sphere-over-checker");
  FrameRenderer renderer(scene, kSize);
  FrameSettings settings;
  auto envmap = renderer.createMethod("envmap", {}, settings);
  const Image expected = renderWith(renderer, *envmap, scene);
  auto fallback = [&] { return renderer.createMethod("envmap", {}, settings); };

  struct Case {
    const char* what;
    MethodGuard::Factory make;
    const char* reason;
  };
  const Case cases[] = {
      {"made",
       [&]() -> std::unique_ptr<Method> { throwGpu("a cube map of 99999 texels a side"); },
       "cube map"},
      {"updated", [] { return std::make_unique<RefusedMethod>(FailIn::kUpdate); }, "99999"},
      {"drawn", [] { return std::make_unique<RefusedMethod>(FailIn::kRender); }, "3 GiB"},
  };
  for (const Case& c : cases) {
    MethodGuard guard("refused", c.make, fallback);
    const Image frame = renderWith(renderer, guard, scene);
    EXPECT_EQ(differingPixels(frame, expected), 0u) << c.what;
    EXPECT_NE(guard.fallbackReason().find(c.reason), std::string::npos)
        << c.what << ": " << guard.fallbackReason();
    EXPECT_EQ(guard.info().name, "envmap") << c.what;
    // The next frame is envmap's too, without another warning.
    EXPECT_EQ(differingPixels(renderWith(renderer, guard, scene), expected), 0u) << c.what;
  }
  // A method the driver accepts is left alone.
  MethodGuard fine(
      "refused", [] { return std::make_unique<RefusedMethod>(FailIn::kNothing); }, fallback);
  renderWith(renderer, fine, scene);
  EXPECT_EQ(fine.fallbackReason(), "");
  EXPECT_EQ(fine.info().name, "refused");
}

TEST_F(MethodGuardTest, AShaderThatDoesNotCompileIsAnErrorNotAFallback) {
  const Scene scene = makeBuiltinScene("sphere-over-checker");
  FrameRenderer renderer(scene, kSize);
  auto fallback = [&] { return renderer.createMethod("envmap", {}, FrameSettings{}); };
  EXPECT_THROW(MethodGuard("broken",
                           []() -> std::unique_ptr<Method> {
                             throw ShaderError("shader 'broken.frag' does not compile");
                           },
                           fallback),
               ShaderError);
}

TEST_F(MethodGuardTest, EnvmapRefusedTooIsAnErrorNamingBoth) {
  expectFallback();
  const Scene scene = makeBuiltinScene("sphere-over-checker");
  FrameRenderer renderer(scene, kSize);
  try {
    MethodGuard guard(
        "refused", [] { return std::make_unique<RefusedMethod>(FailIn::kUpdate); },
        []() -> std::unique_ptr<Method> { throwGpu("cube map size beyond the limit"); });
    renderWith(renderer, guard, scene);
    FAIL() << "no error";
  } catch (const GpuError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("99999"), std::string::npos) << m;
    EXPECT_NE(m.find("cube map size beyond the limit"), std::string::npos) << m;
  }
}

// Through the tool: a real refusal of the real driver (a map past GL_MAX_TEXTURE_SIZE) falls
// back, and says so in the reports; a shader that does not compile (MIRAGE_SHADER_DIR puts a
// broken copy before the embedded one) is a failure, exit 1, naming the file and the log.
TEST_F(MethodGuardTest, TheToolFallsBackFromALimitAndFailsOnABrokenShader) {
  const fs::path dir = testTempDir("guard");
  const std::string common = " --scene mirror-room --size 64x48 -o ";
  const CliResult envmap =
      runMirage("render --method envmap" + common + (dir / "envmap.png").string());
  ASSERT_EQ(envmap.code, 0) << envmap.output;
  const Image expected = readImage((dir / "envmap.png").string());

  const CliResult big = runMirage(
      "render --method zexel --zexel-size 65536" + common + (dir / "zexel.png").string(), "",
      kFallbackExpected);
  ASSERT_EQ(big.code, 0) << big.output;
  EXPECT_NE(big.output.find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << big.output;
  EXPECT_NE(big.output.find("drawing with 'envmap' instead"), std::string::npos) << big.output;
  EXPECT_EQ(differingPixels(readImage((dir / "zexel.png").string()), expected), 0u);

  // compare says so in its report.
  const CliResult report = runMirage(
      "compare --methods zexel,envmap --zexel-size 65536 --scene mirror-room --size 64x48 -o " +
          (dir / "report").string(),
      "", kFallbackExpected);
  ASSERT_EQ(report.code, 0) << report.output;
  std::ifstream in(dir / "report/metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(in);
  const std::string why = metrics["methods"]["zexel"].value("fallback", "");
  EXPECT_NE(why.find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << metrics.dump(1);
  EXPECT_FALSE(metrics["methods"]["envmap"].contains("fallback"));

  writeText(dir / "shaders/methods/impostor/capture_diffuse.frag", "this is not GLSL\n");
  const std::string env = "MIRAGE_SHADER_DIR=" + (dir / "shaders").string();
  const CliResult broken =
      runMirage("render --method billboard" + common + (dir / "billboard.png").string(), env);
  EXPECT_EQ(broken.code, 1) << broken.output;
  EXPECT_NE(broken.output.find("capture_diffuse.frag' does not compile"), std::string::npos)
      << broken.output;
  EXPECT_EQ(broken.output.find("drawing with 'envmap' instead"), std::string::npos)
      << broken.output;
  EXPECT_FALSE(fs::exists(dir / "billboard.png"));
}

}  // namespace
}  // namespace mirage::test
