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

// Camera-path reports: means leave out frames without reflector pixels, the worst frame is the
// lowest PSNR/SSIM and the highest FLIP; the JSON carries per-frame arrays and the kept images,
// the HTML a row per frame and only the kept frames' images, with the reference's for flipping.
TEST(Report, PathMeansAndWorstFrames) {
  ImageMetrics a, b, c;
  a.psnr_reflector = 20.0, b.psnr_reflector = 30.0, c.psnr_reflector = kNan;
  a.flip_reflector = 0.2, b.flip_reflector = 0.1, c.flip_reflector = kNan;
  a.ssim = 0.9, b.ssim = 0.7, c.ssim = 0.8;
  a.reflector_pixels = 100, b.reflector_pixels = 200, c.reflector_pixels = 0;
  ImageMetrics mean = meanMetrics({a, b, c});
  EXPECT_DOUBLE_EQ(mean.psnr_reflector, 25.0);
  EXPECT_DOUBLE_EQ(mean.flip_reflector, 0.15);
  EXPECT_DOUBLE_EQ(mean.ssim, 0.8);
  EXPECT_EQ(mean.reflector_pixels, 100u);
  ImageMetrics worst = worstMetrics({a, b, c});
  EXPECT_DOUBLE_EQ(worst.psnr_reflector, 20.0);
  EXPECT_DOUBLE_EQ(worst.flip_reflector, 0.2);
  EXPECT_DOUBLE_EQ(worst.ssim, 0.7);
  EXPECT_TRUE(std::isnan(meanMetrics({c}).psnr_reflector));
  // An identical frame (infinite PSNR) makes the mean infinite, as for the reference itself.
  a.psnr = kInf, b.psnr = 30.0;
  EXPECT_TRUE(std::isinf(meanMetrics({a, b}).psnr));
  EXPECT_DOUBLE_EQ(worstMetrics({a, b}).psnr, 30.0);
}

CompareReport samplePathReport() {
  CompareReport r = sampleReport();
  r.path.camera = "walk";
  r.path.times = {0.0f, 1.5f, 3.0f, 4.5f, 6.0f};
  for (MethodReport& m : r.methods) {
    for (int f = 0; f < 5; ++f) {
      ImageMetrics x = m.metrics;
      if (m.name != "raytrace") x.psnr_reflector += f;  // 20, 21, ... for envmap
      m.frame_metrics.push_back(x);
      m.frame_ms.push_back(m.ms + f);
    }
    for (int f : {0, 2, 4})
      m.shown.push_back({f, m.name + ".frame" + std::to_string(f) + ".png",
                         m.name + ".frame" + std::to_string(f) + ".err.png",
                         m.name + ".frame" + std::to_string(f) + ".flip.png"});
    m.metrics = meanMetrics(m.frame_metrics);
    m.worst = worstMetrics(m.frame_metrics);
  }
  return r;
}

TEST(Report, PathJsonHasPerFrameArrays) {
  nlohmann::json j = nlohmann::json::parse(metricsJson(samplePathReport()));
  EXPECT_EQ(j["path"]["camera"], "walk");
  EXPECT_EQ(j["path"]["frames"], 5);
  EXPECT_EQ(j["path"]["times"].size(), 5u);
  const nlohmann::json& envmap = j["methods"]["envmap"];
  EXPECT_DOUBLE_EQ(envmap["psnr_reflector"].get<double>(), 22.0);  // the mean
  EXPECT_DOUBLE_EQ(envmap["worst"]["psnr_reflector"].get<double>(), 20.0);
  ASSERT_EQ(envmap["per_frame"]["psnr_reflector"].size(), 5u);
  EXPECT_DOUBLE_EQ(envmap["per_frame"]["psnr_reflector"][4].get<double>(), 24.0);
  EXPECT_DOUBLE_EQ(envmap["per_frame"]["ms"][1].get<double>(), 5.0);
  EXPECT_EQ(envmap["per_frame"]["reflector_pixels"][0], 1234);
  ASSERT_EQ(envmap["images"].size(), 3u);
  EXPECT_EQ(envmap["images"][1]["frame"], 2);
  EXPECT_EQ(envmap["images"][1]["flip_image"], "envmap.frame2.flip.png");
  EXPECT_TRUE(j["methods"]["raytrace"]["per_frame"]["psnr"][0].is_null());  // identical
}

TEST(Report, PathHtmlShowsEveryFrameAndOnlyTheKeptImages) {
  CompareReport r = samplePathReport();
  std::string html = reportHtml(r);
  EXPECT_NE(html.find("Camera path <b>walk</b>: 5 frames"), std::string::npos);
  // The per-frame table: a row per frame with envmap's reflector PSNR.
  for (const char* row : {"<tr><td>0</td><td>0.000</td>", "<tr><td>4</td><td>6.000</td>"})
    EXPECT_NE(html.find(row), std::string::npos) << row;
  EXPECT_NE(html.find(">24.00</td>"), std::string::npos);
  std::set<std::string> used;
  std::regex attr(R"((src|data-ref)=\"([^\"]*)\")");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attr); it != std::sregex_iterator();
       ++it)
    used.insert((*it)[2]);
  for (const MethodReport& m : r.methods)
    for (const ShownFrame& f : m.shown) {
      EXPECT_TRUE(used.count(f.image)) << f.image;
      if (m.name == "raytrace") continue;
      EXPECT_TRUE(used.count(f.error_image)) << f.error_image;
      EXPECT_TRUE(used.count(f.flip_image)) << f.flip_image;
    }
  for (const std::string& v : used) EXPECT_NE(v.find(".frame"), std::string::npos) << v;
  // Pressing envmap's frame-2 image shows the reference's frame 2.
  EXPECT_NE(html.find("src=\"envmap.frame2.png\" alt=\"envmap: frame 2, t = 3.00 s\" "
                      "data-ref=\"raytrace.frame2.png\""),
            std::string::npos);
}

// Per reflector and per cause: the JSON carries them per method and the reference as an object
// with its noise floor; the page marks the best method of each reflector (the reference left
// out) and shows each method's share of squared error per cause.
TEST(Report, RegionsAndTheReferencesNoiseFloor) {
  CompareReport r = sampleReport();
  r.reflector_names = {"left", "right"};
  r.reference_info = {4, true, 64, 41.5, 37.25};
  r.cause_image = "causes.png";
  r.object_layers = {{"floor", "environment"}};
  auto region = [](size_t pixels, double psnr, double sse) {
    RegionMetrics m;
    m.pixels = pixels, m.psnr = psnr, m.sse = sse, m.ssim = 0.9, m.flip = 0.1;
    return m;
  };
  for (MethodReport& m : r.methods) {
    const bool envmap = m.name == "envmap";
    m.regions.reflectors = {{"left", region(1000, envmap ? 25.0 : 15.0, 1.0)},
                            {"right", region(234, envmap ? 11.0 : 14.0, 2.0)}};
    m.regions.has_causes = true;
    m.regions.causes = {{"environment", region(900, 30.0, 1.0)},
                        {"diffuse", region(334, 12.0, 3.0)}};
    m.regions.diffuse_objects = {{"floor", region(334, 12.0, 3.0)}};
    m.regions.layers = {{"environment", region(1234, envmap ? 21.0 : 19.0, 4.0)}};
    m.regions.mixed = region(50, 20.0, 0.5);
  }
  const nlohmann::json j = nlohmann::json::parse(metricsJson(r));
  EXPECT_EQ(j["reference"]["method"], "raytrace");
  EXPECT_EQ(j["reference"]["ssaa"], 4);
  EXPECT_EQ(j["reference"]["noise_floor_psnr_reflector"], 37.25);
  EXPECT_EQ(j["methods"]["envmap"]["reflectors"]["left"]["psnr"], 25.0);
  EXPECT_EQ(j["methods"]["envmap"]["causes"]["diffuse"]["sse"], 3.0);
  EXPECT_EQ(j["methods"]["envmap"]["diffuse_objects"]["floor"]["pixels"], 334);
  EXPECT_EQ(j["methods"]["envmap"]["mixed"]["pixels"], 50);
  EXPECT_EQ(j["methods"]["envmap"]["layers"]["environment"]["psnr"], 21.0);
  EXPECT_EQ(j["object_layers"]["floor"], "environment");
  const std::string html = reportHtml(r);
  // envmap is best on the left reflector, none on the right one.
  EXPECT_NE(html.find("<tr><td>left</td><td>1000</td><td class=best>25.00</td><td>15.00</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<tr><td>right</td><td>234</td><td>11.00</td><td class=best>14.00</td>"),
            std::string::npos);
  EXPECT_NE(html.find("src=\"causes.png\""), std::string::npos);
  // The layer table: each layer, then each object with its layer, the best marked.
  EXPECT_NE(html.find("<tr><td><b>environment</b></td><td></td><td>1234</td><td class=best>21.00"
                      "</td><td>19.00</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<tr><td>floor</td><td>environment</td><td>334</td>"), std::string::npos);
  EXPECT_NE(html.find("75.0%"), std::string::npos);            // diffuse: 3 of the 4 units of sse
  EXPECT_NE(html.find("<b>37.25 dB</b>"), std::string::npos);  // the noise floor
}

}  // namespace
}  // namespace mirage
