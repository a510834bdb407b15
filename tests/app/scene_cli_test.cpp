// Scene input on the command line: a malformed scene file exits with 2 and names the file and the
// field; `mirage scenes` lists asset scenes on stdout once their files exist, on stderr before.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/image.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

struct BadScene {
  std::string label;
  std::string text;
  std::string field;  // the JSON path the message must name
};

void PrintTo(const BadScene& b, std::ostream* os) {
  *os << b.label;
}

class SceneCliBad : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneCliBad, ExitsWithTwoNamingFileAndField) {
  fs::path dir = testTempDir("scene-cli");
  fs::path file = dir / "broken-scene.json";
  std::ofstream(file) << GetParam().text;
  CliResult r = runMirage("render --scene " + file.string() + " --method raytrace -o " +
                          (dir / "x.png").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(GetParam().field), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Cli, SceneCliBad,
    ::testing::Values(
        BadScene{"out of range",
                 R"({"materials": [{"name": "m", "type": "reflector", "fresnel_f0": 1.5}],
                     "meshes": [{"name": "s", "procedural": "sphere"}],
                     "instances": [{"mesh": "s", "material": "m"}]})",
                 "materials[0].fresnel_f0 = 1.5"},
        BadScene{"unknown key",
                 R"({"materials": [{"name": "m", "type": "diffuse"}],
                     "meshes": [{"name": "s", "procedural": "sphere", "radus": 2}],
                     "instances": [{"mesh": "s", "material": "m"}]})",
                 "meshes[0].radus: unknown field"},
        BadScene{"not JSON", "{\"instances\": [", "not valid JSON"},
        BadScene{"empty", "", "empty"}));

TEST(SceneCli, ScenesListsAssetScenesByAvailability) {
  fs::path assets = testTempDir("scene-cli") / "assets";
  fs::create_directories(assets);
  std::string env = "MIRAGE_ASSET_DIR=" + assets.string();
  CliResult out = runMirage("scenes", env, Fallback::kFails, "2>/dev/null");
  CliResult err = runMirage("scenes", env, Fallback::kFails, "2>&1 >/dev/null");
  EXPECT_EQ(out.code, 0);
  EXPECT_NE(out.output.find("spheres9\n"), std::string::npos) << out.output;
  EXPECT_EQ(out.output.find("teapots4"), std::string::npos) << out.output;
  EXPECT_NE(err.output.find("teapots4 (not available"), std::string::npos) << err.output;
  EXPECT_NE(err.output.find("scripts/fetch-assets"), std::string::npos) << err.output;

  // With the teapot and the panoramas (whichever teapots4 uses), it moves to stdout.
  fs::create_directories(assets / "teapot");
  fs::create_directories(assets / "hdri");
  std::ofstream(assets / "teapot/teapot.ply")
      << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  for (const char* hdri :
       {"apartment", "bridge", "city", "dawn", "esplanade", "forest", "hall", "lab", "lobby",
        "night", "park", "sky", "studio", "sunrise", "sunset", "venice", "warehouse", "workshop"})
    writeExr((assets / "hdri" / (std::string(hdri) + ".exr")).string(), Image(8, 4, vec4(1.0f)));
  out = runMirage("scenes", env, Fallback::kFails, "2>/dev/null");
  EXPECT_NE(out.output.find("teapots4\n"), std::string::npos) << out.output;
  CliResult missing = runMirage("render --scene dragon --method raytrace -o x.png", env);
  EXPECT_EQ(missing.code, 2) << missing.output;
  EXPECT_NE(missing.output.find("scripts/fetch-assets"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace mirage::test
