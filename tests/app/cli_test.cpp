// The command-line contract: bad input exits with 2 and one message naming the problem and the
// allowed values; no OpenGL driver exits with 3; good input writes its files.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/builtin_scenes.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

struct BadInput {
  std::string args;
  std::string expected;  // a piece of the message
};

void PrintTo(const BadInput& b, std::ostream* os) {
  *os << "mirage " << b.args;
}

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsWithTwoAndSaysWhy) {
  CliResult r = runMirage(GetParam().args);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().expected), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadInput,
    ::testing::Values(
        BadInput{"render --scene sphere-over-checker --method nope -o x.png", "allowed: none"},
        BadInput{"render --scene no-such-scene --method envmap -o x.png", "no such scene"},
        BadInput{"render --scene sphere-over-checker --method envmap --size 0x10 -o x.png",
                 "1..16384"},
        BadInput{"render --scene sphere-over-checker --method envmap --size banana -o x.png",
                 "WxH"},
        BadInput{"render --scene sphere-over-checker --method envmap --order 99 -o x.png", "0..16"},
        BadInput{"render --scene sphere-over-checker --method envmap -o x.bmp", ".png, .exr"},
        BadInput{"render --scene sphere-over-checker --method envmap --envmap-size 0 -o x.png",
                 "8..2048"},
        BadInput{"render --scene sphere-over-checker --method raytrace --spp 0 -o x.png",
                 "1..4096"},
        BadInput{"render --scene spheres9 --reflectors 12 --method envmap -o x.png", "1..9"},
        BadInput{"render --scene sphere-over-checker --method envmap --tonemap x -o x.png", "aces"},
        BadInput{"render --scene sphere-over-checker --method envmap --mip maybe -o x.png",
                 "on|off"},
        BadInput{"render --scene sphere-over-checker --method envmap --camera nope -o x.png",
                 "no camera"},
        BadInput{"render --method envmap -o x.png", "--scene"},
        BadInput{"render --scene sphere-over-checker --method envmap --bogus 1 -o x.png", "bogus"},
        BadInput{"compare --scene sphere-over-checker --methods envmap,,none -o d", "empty method"},
        BadInput{"compare --scene sphere-over-checker --methods envmap,nope -o d",
                 "unknown method 'nope'"},
        BadInput{"compare --scene mirror-room --reference nope -o d", "unknown method 'nope'"},
        BadInput{"compare --scene mirror-room --camera walk --path-frames -1 -o d", "0..100000"},
        BadInput{"compare --scene mirror-room --path-frames 3 -o d",
                 "camera 'main' of scene 'mirror-room' has no path (cameras with a path: walk"},
        BadInput{"compare --scene sphere-over-checker --path-frames 3 -o d",
                 "no camera of this scene has one"},
        BadInput{"compare --scene mirror-room --camera walk --path-frames 3 --time 1 -o d",
                 "--time cannot be combined with --path-frames"},
        BadInput{"bench --scene sphere-over-checker --frames 0 --json b.json", "1..1000000"},
        BadInput{"render --scene sphere-over-checker --method billboard --order 0 -o x.png",
                 "1..16"},
        BadInput{
            "render --scene sphere-over-checker --method billboard --billboard-size 0 -o x.png",
            "16..4096"},
        BadInput{"render --scene spheres9 --method billboard --billboard-size 1000000 -o x.png",
                 "16..4096"},
        BadInput{"render --scene spheres9 --method billboard --billboard-fov 0 -o x.png", "1..60"},
        BadInput{"render --scene spheres9 --method billboard --billboard-objects some -o x.png",
                 "planar"},
        BadInput{"render --scene ripple-pool --method envmap --frames 0 -o x.png", "1..100000"},
        BadInput{"render --scene ripple-pool --method envmap --frames 3 --fps 0 -o x.png",
                 "(0, 1000]"},
        BadInput{"render --scene ripple-pool --method envmap -o x.mp4", "--frames 2 or more"},
        BadInput{"render --scene ripple-pool --method envmap --time -1 -o x.png", "0..1e6"},
        BadInput{"render --scene ripple-pool --method envmap --camera-path /no/such.json -o x.png",
                 "/no/such.json"},
        BadInput{"bench --scene ripple-pool --fps -2 --json b.json", "0..1000"},
        BadInput{"render --scene mirror-room --method ssr --ssr-steps 4 -o x.png", "8..4096"},
        BadInput{"render --scene mirror-room --method ssr --ssr-thickness 0 -o x.png", "0.0001..1"},
        BadInput{"render --scene mirror-room --method ssr --ssr-thickness inf -o x.png",
                 "0.0001..1"},
        BadInput{"render --scene mirror-room --method ssr --ssr-edge-fade 0.7 -o x.png", "0..0.5"},
        BadInput{"render --scene mirror-room --method ssr --ssr-fallback planar -o x.png",
                 "envmap|envmap-box"},
        BadInput{"frobnicate", "frobnicate"}));

TEST(Cli, HelpExitsZero) {
  for (const char* cmd :
       {"--help", "scenes --help", "render --help", "compare --help", "bench --help"}) {
    CliResult r = runMirage(cmd);
    EXPECT_EQ(r.code, 0) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << cmd;
  }
}

TEST(Cli, ScenesListsTheBuiltInScenesOnStdout) {
  CliResult r = runMirage("scenes 2>/dev/null");
  EXPECT_EQ(r.code, 0);
  for (const char* s : {"sphere-over-checker\n", "spheres9\n", "mirror-room\n", "two-mirrors\n"})
    EXPECT_NE(r.output.find(s), std::string::npos) << r.output;
}

TEST(Cli, ScenesWithANameListsItsInstancesAndTheirLayers) {
  CliResult r = runMirage("scenes mirror-room 2>&1");
  EXPECT_EQ(r.code, 0) << r.output;
  // The room holds the mirror: environment, with its six walls as planar parts.
  EXPECT_NE(r.output.find("room                         environment        12      6  holds "
                          "reflector 'wall-mirror'"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("wall-mirror                  reflector"), std::string::npos);
  EXPECT_NE(r.output.find("pyramid                      object"), std::string::npos);
  r = runMirage("scenes no-such-scene 2>&1");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("no-such-scene: no such scene"), std::string::npos) << r.output;
}

TEST(Cli, NoOpenGLDriverExitsWithThree) {
  auto dir = testTempDir("cli");
  CliResult r =
      runMirage("render --scene sphere-over-checker --method envmap -o " + (dir / "x.png").string(),
                "MIRAGE_NO_GL=1");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("OpenGL 4.5"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

class CliWithGl : public GlTest {};

TEST_F(CliWithGl, RenderWritesPngAndExr) {
  auto dir = testTempDir("cli");
  for (const char* ext : {".png", ".exr"}) {
    auto out = dir / (std::string("img") + ext);
    CliResult r = runMirage("render --scene sphere-over-checker --method envmap --size 96x64 -o " +
                            out.string());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(out), 100u);
  }
  // Nothing but the outputs is left behind (temporary files are renamed or removed).
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 2);
}

TEST_F(CliWithGl, CompareWritesTheReport) {
  auto dir = testTempDir("cli");
  CliResult r = runMirage("compare --scene sphere-over-checker --methods all --size 120x86 -o " +
                          dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"index.html", "metrics.json", "raytrace.png", "envmap.png",
                        "envmap.err.png", "none.png", "envmap-infinite.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
}

// metrics.json under matched sampling: the reference's sampling and noise floor, each method's
// error per reflector, per cause and per layer, and the sums that make each a partition of the
// reflector pixels (pixel counts and squared errors add up to the method's reflector totals).
TEST_F(CliWithGl, CompareSplitsTheErrorByReflectorCauseAndLayer) {
  auto dir = testTempDir("cli");
  CliResult r =
      runMirage("compare --scene spheres9 --methods envmap,billboard --ssaa 2 --size 96x64 -o " +
                dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(dir / "metrics.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& ref = j["reference"];
  EXPECT_EQ(ref["method"], "raytrace");
  EXPECT_EQ(ref["ssaa"], 2);
  EXPECT_EQ(ref["converged_spp"], 64);
  ASSERT_TRUE(ref["noise_floor_psnr"].is_number()) << ref;
  ASSERT_TRUE(ref["noise_floor_psnr_reflector"].is_number()) << ref;
  EXPECT_TRUE(meetsFloor(ref["noise_floor_psnr"].get<double>(), floors::kReferenceNoiseFloor));
  EXPECT_NE(j["timing"].get<std::string>().find("separate run at 96x64"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "causes.png"));
  for (const char* name : {"envmap", "billboard"}) {
    const nlohmann::json& m = j["methods"][name];
    const double pixels = m["reflector_pixels"].get<double>();
    ASSERT_GT(pixels, 100.0) << name;
    // PSNR = 10 log10(1 / MSE) and MSE = SSE / (3 pixels).
    const double sse = 3.0 * pixels * std::pow(10.0, -m["psnr_reflector"].get<double>() / 10.0);
    double cause_pixels = 0.0, cause_sse = 0.0, reflector_pixels = 0.0;
    for (const auto& [cause, c] : m["causes"].items()) {
      cause_pixels += c["pixels"].get<double>();
      cause_sse += c["sse"].get<double>();
    }
    for (const auto& [reflector, c] : m["reflectors"].items())
      reflector_pixels += c["pixels"].get<double>();
    EXPECT_EQ(cause_pixels, pixels) << name;
    EXPECT_NEAR(cause_sse, sse, 1e-6 * sse) << name;
    EXPECT_EQ(reflector_pixels, pixels) << name;
    EXPECT_EQ(m["reflectors"].size(), 9u) << name;  // nine mirror spheres, all in view
    // At order 2 the spheres see the sky, the floor and one another.
    for (const char* cause : {"environment", "diffuse", "reflector"})
      EXPECT_GT(m["causes"][cause]["pixels"].get<double>(), 0.0) << name << " " << cause;
    double objects = 0.0;
    for (const auto& [object, c] : m["diffuse_objects"].items())
      objects += c["pixels"].get<double>();
    EXPECT_EQ(objects, m["causes"]["diffuse"]["pixels"].get<double>()) << name;
    // The layers split the same pixels: the sky and the floor (the environment), the objects,
    // the reflectors.
    double layer_pixels = 0.0, layer_sse = 0.0;
    for (const auto& [layer, c] : m["layers"].items()) {
      layer_pixels += c["pixels"].get<double>();
      layer_sse += c["sse"].get<double>();
    }
    EXPECT_EQ(layer_pixels, pixels) << name;
    EXPECT_NEAR(layer_sse, sse, 1e-6 * sse) << name;
    const double sky_and_floor = m["causes"]["environment"]["pixels"].get<double>() +
                                 m["diffuse_objects"]["floor"]["pixels"].get<double>();
    EXPECT_EQ(m["layers"]["environment"]["pixels"].get<double>(), sky_and_floor) << name;
    EXPECT_EQ(m["layers"]["object"]["pixels"].get<double>(),
              m["causes"]["diffuse"]["pixels"].get<double>() -
                  m["diffuse_objects"]["floor"]["pixels"].get<double>())
        << name;
    EXPECT_GT(m["mixed"]["pixels"].get<double>(), 0.0) << name;
    EXPECT_LT(m["mixed"]["pixels"].get<double>(), pixels) << name;
  }
  EXPECT_EQ(j["object_layers"]["floor"], "environment");
  EXPECT_EQ(j["object_layers"]["teapot"], "object");
  // The reference against itself: no error anywhere.
  for (const auto& [cause, c] : j["methods"]["raytrace"]["causes"].items())
    EXPECT_EQ(c["sse"].get<double>(), 0.0) << cause;
}

// Quality along a walk: every method renders the path's frames in sequence; metrics.json holds
// one value per frame and method, the report keeps the first, middle and last frame's images.
TEST_F(CliWithGl, ComparePathFramesWritesPerFrameMetrics) {
  auto dir = testTempDir("cli");
  CliResult r = runMirage(
      "compare --scene mirror-room --camera walk --path-frames 3 --methods none,planar "
      "--reference planar --order 1 --size 96x64 -o " +
      dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(dir / "metrics.json");
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["reference"]["method"], "planar");
  EXPECT_EQ(j["reference"]["checked"], false);  // the converged check is the ray tracer's
  EXPECT_EQ(j["path"]["camera"], "walk");
  EXPECT_EQ(j["path"]["frames"], 3);
  std::vector<float> times = j["path"]["times"];
  ASSERT_EQ(times.size(), 3u);
  EXPECT_FLOAT_EQ(times[0], 0.0f);  // the walk's first key ...
  EXPECT_FLOAT_EQ(times[1], 3.0f);
  EXPECT_FLOAT_EQ(times[2], 6.0f);  // ... to its last
  ASSERT_EQ(j["methods"].size(), 2u);
  for (const char* name : {"none", "planar"}) {
    const nlohmann::json& m = j["methods"][name];
    for (const char* key : {"psnr", "psnr_reflector", "ssim", "flip_reflector", "ms"})
      EXPECT_EQ(m["per_frame"][key].size(), 3u) << name << "." << key;
    EXPECT_TRUE(m.contains("worst")) << name;
    // Per reflector and per cause, averaged over the frames like the other figures.
    EXPECT_FALSE(m["reflectors"].empty()) << name;
    EXPECT_FALSE(m["causes"].empty()) << name;
    ASSERT_EQ(m["images"].size(), 3u) << name;
    for (const nlohmann::json& image : m["images"])
      for (const char* key : {"image", "error_image", "flip_image"})
        EXPECT_TRUE(std::filesystem::exists(dir / image[key].get<std::string>())) << image;
  }
  // The mirror is in view on every frame: none (base colour) differs from the planar reference
  // there, while the reference against itself is identical (null: infinite PSNR).
  for (const nlohmann::json& v : j["methods"]["none"]["per_frame"]["psnr_reflector"]) {
    ASSERT_TRUE(v.is_number());
    EXPECT_LT(v.get<double>(), 30.0);
  }
  for (const nlohmann::json& v : j["methods"]["planar"]["per_frame"]["psnr_reflector"])
    EXPECT_TRUE(v.is_null());
  // The temporal error: 0 for the reference against itself; for none, whose mirror keeps one
  // colour, its error changes as the reference does, its own change (but on the mirror's
  // outline, where none's pixels are not the mirror's: measured 1.5 % apart).
  EXPECT_EQ(j["methods"]["planar"]["temporal_error_reflector"].get<double>(), 0.0);
  const double change = j["path"]["reference_change_reflector"].get<double>();
  EXPECT_GT(change, 0.01);
  EXPECT_NEAR(j["methods"]["none"]["temporal_error_reflector"].get<double>(), change,
              0.05 * change);
  EXPECT_EQ(j["methods"]["none"]["per_frame"]["temporal_error_reflector"].size(), 3u);
  EXPECT_TRUE(j["methods"]["none"]["per_frame"]["temporal_error_reflector"][0].is_null());
  EXPECT_TRUE(std::filesystem::exists(dir / "index.html"));
  EXPECT_TRUE(std::filesystem::exists(dir / "none.frame1.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "none.png"));  // one view's names are not used
}

TEST_F(CliWithGl, BenchWritesJson) {
  auto dir = testTempDir("cli");
  auto json = dir / "b.json";
  CliResult r = runMirage(
      "bench --scene sphere-over-checker --methods none,envmap,raytrace --frames 3 "
      "--warmup 1 --size 96x64 --json " +
      json.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(json));
}

// What the scene holds and what each method allocated: envmap's probe (one cube of
// --envmap-size faces, RGBA16F, full mips) is most of its storage, the ray tracer holds none.
TEST_F(CliWithGl, BenchJsonCountsObjectsAndGpuBytes) {
  auto dir = testTempDir("cli");
  const auto bench = [&](const std::string& extra) {
    auto json = dir / "b.json";
    CliResult r = runMirage(
        "bench --scene sphere-over-checker --methods none,envmap,raytrace --frames 2 "
        "--warmup 1 --size 96x64 --json " +
        json.string() + extra);
    EXPECT_EQ(r.code, 0) << r.output;
    std::ifstream in(json);
    return nlohmann::json::parse(in);
  };
  const nlohmann::json small = bench(" --envmap-size 64"), large = bench(" --envmap-size 128");
  const Scene scene = makeBuiltinScene("sphere-over-checker", {});
  EXPECT_EQ(small["objects"], scene.instances.size());
  EXPECT_EQ(small["reflectors"], scene.reflectorInstances().size());
  EXPECT_GT(small["gpu_bytes_shared"].get<int64_t>(), 0);
  EXPECT_EQ(small["methods"]["raytrace"]["gpu_bytes"], 0);
  // One RGBA16F cube with full mips grows by 6 faces x (128^2 - 64^2) x 4/3 texels x 8 bytes
  // from 64- to 128-texel faces; envmap holds one such cube per level of its order (2) and a
  // capture target of the face size, so it grows by 1 to 4 times that.
  const double cube_growth = 6.0 * double((4 * 128 * 128 - 1) / 3 - (4 * 64 * 64 - 1) / 3) * 8.0;
  const double grown = double(large["methods"]["envmap"]["gpu_bytes"].get<int64_t>() -
                              small["methods"]["envmap"]["gpu_bytes"].get<int64_t>());
  EXPECT_GE(grown, cube_growth);
  EXPECT_LE(grown, 4.0 * cube_growth)
      << "envmap gpu_bytes " << small["methods"]["envmap"]["gpu_bytes"] << " -> "
      << large["methods"]["envmap"]["gpu_bytes"];
}

}  // namespace
}  // namespace mirage::test
