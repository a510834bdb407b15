// Hostile and broken inputs through the tool itself: every one exits 2 with one message naming
// the file and what is wrong, quickly (nothing huge allocated, nothing hangs). The run writes its
// rows — input, command, exit code, seconds, message — to test-artifacts/hostile-inputs.json, the
// raw figures of docs/reliability.md's table (`scripts/docs-figures --only hostile-inputs`
// formats them).
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/image.h"
#include "scene/model_loader_files.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

struct Hostile {
  std::string what;                    // the row's description
  std::string file;                    // written into the test folder ("" for none)
  std::function<std::string()> bytes;  // its content
  std::string args;                    // {} stands for the file's path
  std::vector<std::string> expect;     // parts of the message
};

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

std::string plyHeader(const std::string& vertices, const std::string& faces) {
  return "ply\nformat ascii 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string triangle(const std::string& face) {
  return plyHeader("3", "1") + "0 0 0\n1 0 0\n0 1 0\n" + face + "\n";
}

std::string sceneWith(const std::string& fields) {
  return R"({"name": "hostile", "materials": [{"name": "m", "type": "diffuse"}],)" + fields + "}";
}

// A scene of one mesh "s" (its fields after the name) drawn once with material "m"; `extra`
// adds sections before it.
std::string sceneWithMesh(const std::string& mesh_fields, const std::string& extra = "") {
  return sceneWith(extra + R"("meshes": [{"name": "s", )" + mesh_fields +
                   R"(}], "instances": [{"mesh": "s", "material": "m"}])");
}

std::string sceneWithEnvironment(const std::string& image) {
  return sceneWithMesh(R"("procedural": "sphere")",
                       R"("environment": {"image": ")" + image + R"("}, )");
}

std::string gltfWith(const std::string& accessor_count, const std::string& indices = "") {
  return R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
         accessor_count + R"(, "type": "VEC3"})" + indices + R"(],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0})" +
         (indices.empty() ? "" : R"(, "indices": 1)") + R"(}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
}

// A real image of `w`x`h`, its header then patched (big-endian 32-bit fields).
std::string pngClaiming(uint32_t w, uint32_t h) {
  const fs::path p = testTempDir("hostile-png") / "small.png";
  writePng(p.string(), Image(4, 4, vec4(0.5f)));
  std::string png = readFile(p.string());
  for (int i = 0; i < 4; ++i) {
    png[16 + size_t(i)] = char((w >> (24 - 8 * i)) & 0xff);
    png[20 + size_t(i)] = char((h >> (24 - 8 * i)) & 0xff);
  }
  return png;
}

// A real EXR whose dataWindow attribute is made to claim max+1 pixels a side.
std::string exrClaiming(int32_t max) {
  const fs::path p = testTempDir("hostile-exr") / "small.exr";
  writeExr(p.string(), Image(2, 2, vec4(0.5f)));
  std::string exr = readFile(p.string());
  const std::string key("dataWindow\0box2i\0", 17);
  const size_t at = exr.find(key);
  if (at == std::string::npos) return exr;
  const size_t box = at + key.size() + 4;  // past the attribute's 4-byte size
  std::memcpy(&exr[box + 8], &max, 4);     // xMax
  std::memcpy(&exr[box + 12], &max, 4);    // yMax
  return exr;
}

std::string hdrClaiming(const std::string& resolution) {
  return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" + resolution + "\n" + std::string(64, '\x80');
}

// Meshes: PLY, plain and compressed.
std::vector<Hostile> plyInputs(const std::string& render) {
  return {
      {"PLY header claiming 10^12 vertices",
       "huge.ply",
       [] { return plyHeader("1000000000000", "1"); },
       render + "{}",
       {"huge.ply", "1000000000000 vertices", "at most 50000000"}},
      {"PLY header with a negative count",
       "negative.ply",
       [] { return plyHeader("-5", "1"); },
       render + "{}",
       {"negative.ply", "line 3", "-5"}},
      {"PLY header with a misspelt keyword (free text is a comment, this is not)",
       "misspelt.ply",
       [] {
         std::string text = triangle("3 0 1 2");
         return text.replace(text.find("element face"), 7, "elment");
       },
       render + "{}",
       {"misspelt.ply", "line 7", "misspelt 'element'"}},
      {"PLY face index out of range",
       "index.ply",
       [] { return triangle("3 0 1 7"); },
       render + "{}",
       {"index.ply", "7"}},
      {"PLY within the vertex limit, over --max-memory",
       "big.ply",
       [] { return plyHeader("1000000", "2000000"); },
       render + "{} --max-memory 16M",
       {"big.ply", "--max-memory", "16 MiB"}},
      {"gzip bomb: 1 GiB of zeros in a 1 MiB .ply.gz",
       "bomb.ply.gz",
       [] { return gzip(triangle("3 0 1 2") + std::string(size_t(1) << 30, '\0')); },
       render + "{} --max-memory 64M",
       {"bomb.ply.gz", "decompresses to more than 64 MiB"}},
      {"PLY with a NaN coordinate",
       "nan.ply",
       [] { return replaceAll(triangle("3 0 1 2"), "1 0 0", "nan 0 0"); },
       render + "{}",
       {"nan.ply", "non-finite"}},
  };
}

// Meshes: OBJ, glTF and GLB.
std::vector<Hostile> objGltfInputs(const std::string& render) {
  return {
      {"OBJ with an inf coordinate",
       "inf.obj",
       [] { return "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n"; },
       render + "{}",
       {"inf.obj", "line 2", "non-finite position"}},
      {"OBJ face index out of range",
       "face.obj",
       [] { return "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"; },
       render + "{}",
       {"face.obj", "9"}},
      {"glTF accessor claiming 10^12 vertices",
       "count.gltf",
       [] { return gltfWith("1000000000000"); },
       render + "{}",
       {"count.gltf", "1000000000000"}},
      {"glTF accessor larger than its buffer",
       "short.gltf",
       [] { return gltfWith("1000"); },
       render + "{}",
       {"short.gltf", "accessor 0"}},
      {"glTF index out of range",
       "indices.gltf",
       [] {
         return replaceAll(
             gltfWith(
                 "3",
                 R"(, {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"})"),
             R"("bufferViews": [{"buffer": 0, "byteLength": 36}])",
             R"("bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 24, "byteLength": 12}])");
       },
       render + "{}",
       {"indices.gltf"}},
      {"glTF buffer whose uri names a folder",
       "folder-buffer.gltf",
       [] {
         return replaceAll(gltfWith("3"),
                           "data:application/octet-stream;base64,"
                           "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA",
                           "folder.ply");
       },
       render + "{}",
       {"folder-buffer.gltf", "folder.ply"}},
      {"GLB cut short",
       "cut.glb",
       [] { return std::string("glTF\x02\0\0\0\x00\x10\0\0", 12); },
       render + "{}",
       {"cut.glb"}},
  };
}

// Images: PNG, EXR and Radiance HDR.
std::vector<Hostile> imageInputs(const std::string& render) {
  return {
      {"PNG claiming 1,000,000 x 1,000,000 pixels",
       "huge.png",
       [] { return pngClaiming(1000000, 1000000); },
       "",
       {"huge.png", "1000000x1000000", "outside the supported range"}},
      {"PNG of 8192 x 8192 over --max-memory 1G",
       "big.png",
       [] { return pngClaiming(8192, 8192); },
       render + "{} --max-memory 1G",
       {"big.png", "8192x8192", "2.0 GiB", "--max-memory allows 1.0 GiB"}},
      {"EXR whose data window claims 10^6 pixels a side",
       "huge.exr",
       [] { return exrClaiming(999999); },
       "",
       {"huge.exr", "1000000x1000000"}},
      {"Radiance HDR claiming 100,000 x 100,000",
       "huge.hdr",
       [] { return hdrClaiming("-Y 100000 +X 100000"); },
       "",
       {"huge.hdr", "100000x100000"}},
      {"Radiance HDR run of length 0 (stb would loop forever)",
       "zero-run.hdr",
       [] { return readFile(MIRAGE_FUZZ_CORPUS "/hdr/regression-rle-zero-count.hdr"); },
       "",
       {"zero-run.hdr", "scanline"}},
      {"empty image file", "empty.exr", [] { return std::string(); }, "", {"empty.exr", "empty"}},
  };
}

// Scene, camera and event files.
std::vector<Hostile> sceneFileInputs(const std::string& render) {
  return {
      {"scene JSON cut short",
       "cut.json",
       [] { return std::string(R"({"name": "x", "materials": [)"); },
       render + "{}",
       {"cut.json", "line 1"}},
      {"scene JSON nested 100,000 deep",
       "deep.json",
       [] { return std::string(100000, '[') + std::string(100000, ']'); },
       render + "{}",
       {"deep.json"}},
      {"scene JSON radius of 1e39",
       "large.json",
       [] { return sceneWithMesh(R"("procedural": "sphere", "radius": 1e39)"); },
       render + "{}",
       {"large.json", "radius", "outside the allowed range"}},
      {"scene JSON number beyond a double",
       "overflow.json",
       [] { return sceneWithMesh(R"("procedural": "sphere", "radius": 1e999)"); },
       render + "{}",
       {"overflow.json", "1e999"}},
      {"scene JSON sphere of 10^9 segments",
       "segments.json",
       [] { return sceneWithMesh(R"("procedural": "sphere", "segments": 1000000000)"); },
       render + "{}",
       {"segments.json", "segments", "3..2048"}},
      {"scene JSON subdividing a mesh 12 times",
       "subdivide.json",
       [] { return sceneWithMesh(R"("file": "box.ply", "subdivide": 12)"); },
       render + "{}",
       {"subdivide.json", "subdivide = 12", "0..4"}},
      {"scene JSON naming a missing mesh file",
       "missing.json",
       [] { return sceneWithMesh(R"("file": "nowhere.ply")"); },
       render + "{}",
       {"nowhere.ply"}},
      {"binary garbage as a scene",
       "garbage.json",
       [] { return std::string("\x89\xff\x00\x13garbage", 11); },
       render + "{}",
       {"garbage.json"}},
      {"camera file with fov_y 180",
       "camera.json",
       [] { return std::string(R"({"position": [0, 1, 3], "target": [0, 0, 0], "fov_y": 180})"); },
       "render --method envmap --size 32x32 -o out.png --scene sphere-over-checker --camera-path "
       "{}",
       {"camera.json", "fov_y", "180"}},
      {"camera path with keys out of order",
       "path.json",
       [] {
         return std::string(
             R"({"fov_y": 50, "path": [{"time": 1, "position": [0, 1, 3], "target": [0, 0, 0]}, {"time": 0, "position": [0, 1, 2], "target": [0, 0, 0]}]})");
       },
       "render --method envmap --size 32x32 -o out.png --scene sphere-over-checker --camera-path "
       "{}",
       {"path.json", "time"}},
      {"event script with an unknown key",
       "events.json",
       [] {
         return std::string(
             R"({"events": [{"frame": 1, "type": "key", "key": "NOT_A_KEY", "down": true}]})");
       },
       "view --scene sphere-over-checker --frames 2 --events {}",
       {"events.json", "NOT_A_KEY"}},
  };
}

// Options and names on the command line.
std::vector<Hostile> optionInputs(const std::string& render) {
  return {
      {"a folder given as a mesh", "", nullptr, render + "folder.ply", {"folder.ply", "folder"}},
      {"--max-memory out of range",
       "",
       nullptr,
       render + "sphere-over-checker --max-memory 10",
       {"--max-memory 10", "1M..1T"}},
      {"--size 0x0",
       "",
       nullptr,
       "render --method envmap --size 0x0 -o out.png --scene sphere-over-checker",
       {"--size 0x0", "1..16384"}},
      {"--ssaa 0", "", nullptr, render + "sphere-over-checker --ssaa 0", {"--ssaa 0", "1..8"}},
      {"--ssaa 9",
       "",
       nullptr,
       "compare --methods envmap --size 32x32 -o report --scene sphere-over-checker --ssaa 9",
       {"--ssaa 9", "1..8"}},
      {"--ssaa 8 beyond the driver's largest frame",
       "",
       nullptr,
       "render --method envmap --size 4200x4200 -o out.png --scene sphere-over-checker --ssaa 8",
       {"--ssaa 8", "33600x33600", "largest frame side"}},
      {"--ssaa 4 over --max-memory",
       "",
       nullptr,
       "compare --methods envmap --size 2048x2048 -o report --scene sphere-over-checker "
       "--ssaa 4 --max-memory 1G",
       {"--ssaa 4", "8192x8192", "--max-memory allows 1.0 GiB"}},
      {"unknown method",
       "",
       nullptr,
       "render --method mirrorball -o out.png --scene sphere-over-checker",
       {"mirrorball", "allowed"}},
  };
}

std::vector<Hostile> hostileInputs() {
  const std::string render = "render --method envmap --size 32x32 -o out.png --scene ";
  std::vector<Hostile> all;
  for (auto group : {plyInputs, objGltfInputs, imageInputs, sceneFileInputs, optionInputs})
    for (Hostile& h : group(render)) all.push_back(std::move(h));
  return all;
}

// The message without the test folder's path, first line only, bytes past ASCII escaped.
std::string errorLine(std::string out, const std::string& dir) {
  out = replaceAll(out, dir + "/", "");
  const size_t error = out.rfind("mirage: error: ");
  if (error != std::string::npos) out = out.substr(error);
  out = out.substr(0, out.find('\n'));
  std::string printable;  // the input's own bytes may be echoed: keep the table UTF-8
  for (unsigned char c : out)
    printable += c < 0x80 ? std::string(1, char(c)) : fmt::format("\\x{:02x}", c);
  return printable;
}

TEST(HostileInputs, EachExitsTwoWithAMessageNamingWhatIsWrong) {
  const std::string render = "render --method envmap --size 32x32 -o out.png --scene ";
  const fs::path dir = testTempDir("hostile");
  fs::create_directories(dir / "folder.ply");
  writeText(dir / "box.ply", boxPlyText());
  nlohmann::json rows = nlohmann::json::array();
  for (const Hostile& h : hostileInputs()) {
    std::string args = h.args;
    if (!h.file.empty()) {
      std::ofstream(dir / h.file, std::ios::binary) << h.bytes();
      // An image is the environment of a scene written beside it: {} is then that scene.
      const fs::path ext = fs::path(h.file).extension();
      std::string target = h.file;
      if (ext == ".png" || ext == ".exr" || ext == ".hdr") {
        target = h.file + ".scene.json";
        std::ofstream(dir / target) << sceneWithEnvironment(h.file);
      }
      args = replaceAll(args.empty() ? render + "{}" : args, "{}", target);
    }
    fs::remove(dir / "out.png");
    const auto start = std::chrono::steady_clock::now();
    const CliResult run = runMirage(args, "cd " + dir.string() + " &&");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(run.code, 2) << h.what << "\n" << run.output;
    for (const std::string& part : h.expect)
      EXPECT_NE(run.output.find(part), std::string::npos)
          << h.what << ": the message lacks '" << part << "'\n"
          << run.output;
    EXPECT_NE(run.output.find("mirage: error: "), std::string::npos) << h.what << "\n"
                                                                     << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png")) << h.what;
    EXPECT_FALSE(fs::exists(dir / "report")) << h.what;  // compare's folder: not even made
    rows.push_back({{"input", h.what},
                    {"command", args},
                    {"exit", run.code},
                    {"seconds", seconds},
                    {"message", errorLine(run.output, dir.string())}});
  }
  fs::create_directories(MIRAGE_TEST_ARTIFACTS);
  writeFileAtomic(std::string(MIRAGE_TEST_ARTIFACTS) + "/hostile-inputs.json", rows.dump(1) + "\n");
}

}  // namespace
}  // namespace mirage::test
