// `mirage compare` end to end: the FLIP maps and figures land in the report, and they rank the
// methods the way the images do (the reference against itself is 0; no reflections at all is
// worse on the reflectors than an environment-map approximation).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "support/gl_test.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

class CompareFlip : public GlTest {};

TEST_F(CompareFlip, ReportHasFlipMapsAndFigures) {
  auto dir = testTempDir("compare-flip");
  CliResult r =
      runMirage("compare --scene sphere-over-checker --methods none,envmap --size 160x112 -o " +
                dir.string());
  ASSERT_EQ(r.code, 0) << r.output;

  for (const char* name : {"raytrace", "none", "envmap"}) {
    auto flip = dir / (std::string(name) + ".flip.png");
    ASSERT_TRUE(std::filesystem::exists(flip)) << flip;
    Image map = readImage(flip.string(), Encoding::kLinear);
    EXPECT_EQ(map.size(), ivec2(160, 112));
  }
  std::ifstream in(dir / "metrics.json");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str());
  const nlohmann::json& m = j["methods"];
  EXPECT_EQ(m["raytrace"]["flip"].get<double>(), 0.0);
  EXPECT_EQ(m["raytrace"]["flip_reflector"].get<double>(), 0.0);
  double none = m["none"]["flip_reflector"].get<double>();
  double envmap = m["envmap"]["flip_reflector"].get<double>();
  EXPECT_GT(none, 0.0);
  EXPECT_LE(none, 1.0);
  EXPECT_GT(envmap, 0.0);
  EXPECT_LT(envmap, none);
  // Reflector pixels are a part of the image, and only they differ much.
  EXPECT_LT(m["none"]["flip"].get<double>(), none);

  std::ifstream html_in(dir / "index.html");
  std::stringstream html;
  html << html_in.rdbuf();
  EXPECT_NE(html.str().find("src=\"envmap.flip.png\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mirage::test
