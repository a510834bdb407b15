// `mirage advise` end to end on gallery, small: its files, a choice that is the least error
// within the budget, a measured composite that is what it predicted, and the errors.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json readJsonFile(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

class AdviseCli : public GlTest {};

TEST_F(AdviseCli, ChoosesTheLeastErrorWithinTheBudgetAndMeasuresIt) {
  const fs::path dir = testTempDir("advise-cli");
  const std::string common =
      "advise --scene gallery --size 96x64 --ssaa 2 --views 1 --frames 2 "
      "--methods none,envmap-box,planar ";
  const CliResult r = runMirage(common + "--budget 1000 -o " + (dir / "free").string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"advice.json", "assignment.json", "assign.txt", "report.html"})
    EXPECT_TRUE(fs::exists(dir / "free" / f)) << f;
  const nlohmann::json a = readJsonFile(dir / "free/advice.json");
  // With no limit that matters, each reflector gets its least-error candidate.
  std::map<std::string, double> least;
  for (const auto& c : a["candidates"]) {
    const std::string name = c["reflector"];
    const double sse = c["sse"];
    if (!least.count(name) || sse < least[name]) least[name] = sse;
  }
  for (const auto& c : a["candidates"]) {
    if (c["chosen"].get<bool>()) {
      EXPECT_EQ(c["sse"].get<double>(), least[c["reflector"]]);
    }
  }
  // The wall mirrors are exact with planar, the curved ones are not planar's.
  EXPECT_NE(a["assignment"].get<std::string>().find("mirror-back,mirror-left=planar"),
            std::string::npos)
      << a["assignment"];
  // Each reflector's pixels in the composite are its own method's (MixedMethod.*): the
  // measured quality is the predicted one, but for output pixels on an outline whose sub-pixels
  // (--ssaa 2) fall on two reflectors drawn by different methods in the composite (measured:
  // 0.012 dB).
  EXPECT_NEAR(a["measured"]["psnr_reflector"].get<double>(),
              a["predicted"]["psnr_reflector"].get<double>(), 0.1);
  EXPECT_GE(a["measured"]["psnr_reflector"].get<double>(),
            a["best_single"]["psnr_reflector"].get<double>());
  // The scene JSON is a scene file's "reflections", which the command line takes back.
  const nlohmann::json scene_json = readJsonFile(dir / "free/assignment.json");
  ASSERT_TRUE(scene_json["reflections"].is_array());
  std::ifstream flags(dir / "free/assign.txt");
  std::string line;
  std::getline(flags, line);
  const CliResult again = runMirage("render --scene gallery --size 96x64 " + line + " -o " +
                                    (dir / "again.png").string());
  EXPECT_EQ(again.code, 0) << again.output;
}

TEST_F(AdviseCli, NothingFitsSaysWhatTheCheapestCosts) {
  const fs::path dir = testTempDir("advise-cli-tight");
  const CliResult r = runMirage(
      "advise --scene gallery --size 64x48 --ssaa 1 --views 0 --frames 1 --methods "
      "none,planar --budget 0.001 -o " +
      (dir / "out").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("nothing fits in 0.00 ms; the cheapest assignment"), std::string::npos)
      << r.output;
  for (const char* bad :
       {"--budget x", "--budget -3", "--budget 0x", "--methods raytrace", "--views 99"}) {
    const CliResult b = runMirage(std::string("advise --scene gallery --size 64x48 ") + bad +
                                  " -o " + (dir / "bad").string());
    EXPECT_EQ(b.code, 2) << bad << ": " << b.output;
  }
}

// A candidate that fails (here zexel, through a broken copy of its resolve shader put before the
// embedded one: a shader of ours that does not compile, an error and no fallback) is reported in
// advice.json and the report with its reason, and the others are advised on; only when every
// candidate fails is advise an error (exit 1).
TEST_F(AdviseCli, ACandidateThatFailsIsReportedAndLeftOut) {
  const fs::path dir = testTempDir("advise-cli-failed");
  writeText(dir / "shaders/methods/zexel/zexel_resolve.comp", "this is not GLSL\n");
  const std::string env = "MIRAGE_SHADER_DIR=" + (dir / "shaders").string();
  const std::string common =
      "advise --scene gallery --size 64x48 --ssaa 1 --views 0 --frames 1 --budget 1000 ";
  const CliResult r =
      runMirage(common + "--methods envmap-box,zexel -o " + (dir / "out").string(), env);
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json a = readJsonFile(dir / "out/advice.json");
  ASSERT_EQ(a["failed"].size(), 2u) << a["failed"].dump(1) << "zexel and zexel:zexel-size=256";
  for (const auto& f : a["failed"]) {
    EXPECT_EQ(f["candidate"].get<std::string>().rfind("zexel", 0), 0u) << f.dump();
    EXPECT_NE(f["reason"].get<std::string>().find("zexel_resolve.comp' does not compile"),
              std::string::npos)
        << f.dump();
  }
  for (const auto& c : a["candidates"])
    EXPECT_EQ(c["candidate"].get<std::string>().rfind("envmap-box", 0), 0u) << c.dump();
  EXPECT_NE(a["assignment"].get<std::string>().find("envmap-box"), std::string::npos);
  std::ifstream html(dir / "out/report.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("Candidates that failed"), std::string::npos);

  const CliResult none = runMirage(common + "--methods zexel -o " + (dir / "none").string(), env);
  EXPECT_EQ(none.code, 1) << none.output;
  EXPECT_NE(none.output.find("every candidate failed"), std::string::npos) << none.output;
}

}  // namespace
}  // namespace mirage::test
