// The compare report: metrics.json keeps the fields other tools read and adds FLIP; the HTML
// escapes what it shows, loads nothing from outside, ranks honestly and shows the reference first.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "eval/heatmap.h"
#include "eval/report.h"

namespace mirage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

MethodReport method(const std::string& name, double psnr_r, double flip_r, double ms) {
  MethodReport m;
  m.name = name;
  m.description = name + " description";
  m.metrics.psnr = psnr_r + 10.0;
  m.metrics.psnr_reflector = psnr_r;
  m.metrics.ssim = 0.9;
  m.metrics.ssim_reflector = 0.5;
  m.metrics.flip = flip_r / 10.0;
  m.metrics.flip_reflector = flip_r;
  m.metrics.reflector_pixels = 1234;
  m.ms = ms;
  m.first_ms = 2.0 * ms;
  m.order_rendered = 2;
  m.image = name + ".png";
  m.error_image = name + ".err.png";
  m.flip_image = name + ".flip.png";
  return m;
}

CompareReport sampleReport() {
  CompareReport r;
  r.scene = "sphere-over-checker";
  r.size = {720, 512};
  r.order = 2;
  r.heatmap_max = 0.25f;
  r.flip_ppd = 67.02f;
  MethodReport ref = method("raytrace", kInf, 0.0, 900.0);
  ref.metrics.psnr = kInf;
  ref.metrics.ssim = ref.metrics.ssim_reflector = 1.0;
  r.methods = {ref, method("envmap", 20.0, 0.15, 4.0), method("none", 12.0, 0.45, 2.0)};
  return r;
}

TEST(Report, JsonKeepsTheOldFieldsAndAddsFlip) {
  nlohmann::json j = nlohmann::json::parse(metricsJson(sampleReport()));
  EXPECT_EQ(j["scene"], "sphere-over-checker");
  EXPECT_EQ(j["size"], nlohmann::json::array({720, 512}));
  EXPECT_NEAR(j["flip_pixels_per_degree"].get<double>(), 67.02, 1e-3);
  ASSERT_EQ(j["methods"].size(), 3u);
  for (const char* name : {"raytrace", "envmap", "none"}) {
    const nlohmann::json& m = j["methods"][name];
    for (const char* key : {"psnr", "psnr_reflector", "ssim", "ssim_reflector", "ms",
                            "reflector_pixels", "flip", "flip_reflector"})
      EXPECT_TRUE(m.contains(key)) << name << "." << key;
  }
  const nlohmann::json& envmap = j["methods"]["envmap"];
  EXPECT_DOUBLE_EQ(envmap["psnr_reflector"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(envmap["flip"].get<double>(), 0.015);
  EXPECT_DOUBLE_EQ(envmap["flip_reflector"].get<double>(), 0.15);
  EXPECT_EQ(envmap["reflector_pixels"], 1234);
  // Identical (+inf PSNR) is null, as before; FLIP 0 stays a number.
  EXPECT_TRUE(j["methods"]["raytrace"]["psnr"].is_null());
  EXPECT_EQ(j["methods"]["raytrace"]["flip"], 0.0);
}

TEST(Report, JsonWritesNullForMissingFlip) {
  CompareReport r = sampleReport();
  r.methods[1].metrics.flip_reflector = kNan;  // no reflector pixels
  nlohmann::json j = nlohmann::json::parse(metricsJson(r));
  EXPECT_TRUE(j["methods"]["envmap"]["flip_reflector"].is_null());
}

TEST(Report, HtmlEscapesNamesAndDescriptions) {
  CompareReport r = sampleReport();
  r.scene = "<b>scene</b>";
  r.scene_description = "a \"quoted\" & 'odd' one";
  r.methods[2].name = "<img src=x onerror=alert(1)>";
  r.methods[2].description = "</p><script>alert(2)</script>";
  r.methods[2].note = "<i>note</i>";
  std::string html = reportHtml(r);
  EXPECT_EQ(html.find("<img src=x"), std::string::npos);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(html.find("<b>scene</b>"), std::string::npos);
  EXPECT_EQ(html.find("<i>note"), std::string::npos);
  EXPECT_NE(html.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
  EXPECT_NE(html.find("&lt;/p&gt;&lt;script&gt;alert(2)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("a &quot;quoted&quot; &amp; &#39;odd&#39; one"), std::string::npos);
}

TEST(Report, HtmlLoadsOnlyTheReportsOwnImages) {
  CompareReport r = sampleReport();
  std::string html = reportHtml(r);
  std::set<std::string> own;
  for (const MethodReport& m : r.methods) own.insert({m.image, m.error_image, m.flip_image});
  std::set<std::string> used;
  std::regex attr(R"((src|href|data-ref)=\"([^\"]*)\")");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attr); it != std::sregex_iterator();
       ++it) {
    std::string v = (*it)[2];
    if ((*it)[1] == "href") {
      EXPECT_TRUE(v == "#reference" || v.rfind("#m-", 0) == 0) << v;  // in-page links only
    } else {
      EXPECT_TRUE(own.count(v)) << v;
      used.insert(v);
    }
  }
  // Every method's three images are shown; the reference's maps (all black) are not.
  for (const MethodReport& m : r.methods) {
    EXPECT_TRUE(used.count(m.image)) << m.image;
    if (m.name == "raytrace") continue;
    EXPECT_TRUE(used.count(m.error_image)) << m.error_image;
    EXPECT_TRUE(used.count(m.flip_image)) << m.flip_image;
  }
  for (const char* outside : {"http:", "https:", "<link", "@import", "url("})
    EXPECT_EQ(html.find(outside), std::string::npos) << outside;
}

TEST(Report, HtmlShowsTheReferenceFirstAndMarksTheBestValues) {
  std::string html = reportHtml(sampleReport());
  size_t ref = html.find("src=\"raytrace.png\""), envmap = html.find("src=\"envmap.png\"");
  ASSERT_NE(ref, std::string::npos);
  ASSERT_NE(envmap, std::string::npos);
  EXPECT_LT(ref, envmap);
  // Best among the methods other than the reference: envmap's PSNR/FLIP, none's ms. The
  // reference (infinite PSNR, FLIP 0) is not ranked.
  EXPECT_NE(html.find("<td data-v=\"20\" class=best>20.00</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"0.15\" class=best>0.1500</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"2\" class=best>2.00</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"0.45\">0.4500</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"Infinity\">&infin;</td>"), std::string::npos);
  EXPECT_EQ(html.find("<td data-v=\"0\" class=best>"), std::string::npos);
  // The columns and the reading note are there.
  for (const char* text :
       {"FLIP reflector", "PSNR reflector", "How to read", "67.0 pixels per degree"})
    EXPECT_NE(html.find(text), std::string::npos) << text;
}

TEST(Report, ColourBarsUseTheMapsColours) {
  // The legend is a CSS gradient through the magma stops: its ends must be the colours the PNGs
  // use for 0 and for the top of the scale.
  std::string html = reportHtml(sampleReport());
  auto css = [](vec3 c) {
    c *= 255.0f;
    return "rgb(" + std::to_string(std::lround(c.x)) + "," + std::to_string(std::lround(c.y)) +
           "," + std::to_string(std::lround(c.z)) + ")";
  };
  EXPECT_NE(html.find(css(magma(0.0f)) + " 0%"), std::string::npos);
  EXPECT_NE(html.find(css(magma(0.5f)) + " 50%"), std::string::npos);
  EXPECT_NE(html.find(css(magma(1.0f)) + " 100%"), std::string::npos);
  EXPECT_NE(html.find("&ge; 0.25"), std::string::npos);  // the |error| bar's top
}

TEST(Report, WritesBothFiles) {
  auto dir = std::filesystem::temp_directory_path() / "mirage-report-test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  writeCompareReport(dir.string(), sampleReport());
  std::ifstream json(dir / "metrics.json");
  std::stringstream text;
  text << json.rdbuf();
  EXPECT_TRUE(nlohmann::json::parse(text.str())["methods"].contains("envmap"));
  EXPECT_GT(std::filesystem::file_size(dir / "index.html"), 1000u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mirage
