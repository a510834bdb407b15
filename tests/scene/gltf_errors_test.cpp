// Malformed glTF files: every one must give an InputError naming the file and what is wrong.
#include <gtest/gtest.h>

#include "scene/gltf_test_files.h"
#include "scene/log_capture.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"

namespace mirage {
namespace {

using nlohmann::json;
using test::expectInputError;
using test::TempDir;

TEST(GltfErrors, AccessorOutsideItsBufferView) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["accessors"][0]["count"] = 40;  // POSITION runs past the view
  std::string path = test::writeGltf(dir, s);
  expectInputError([&] { loadGltf(path); },
                   {path, "mesh 'quad' primitive 0 POSITION", "accessor 0", "does not fit"});
}

TEST(GltfErrors, BufferViewOutsideItsBuffer) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["bufferViews"][1]["byteOffset"] = 4000;
  std::string path = test::writeGltf(dir, s);
  // tinygltf or mirage may notice first; either way the file is named.
  expectInputError([&] { loadGltf(path); }, {path});
}

TEST(GltfErrors, StrideSmallerThanAnElement) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["bufferViews"][0]["byteStride"] = 4;
  std::string path = test::writeGltf(dir, s);
  expectInputError([&] { loadGltf(path); }, {path, "byteStride 4", "12 bytes"});
}

TEST(GltfErrors, IndexOutOfRange) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  for (int a : {0, 1, 2}) s.doc["accessors"][a]["count"] = 3;  // index 3 is now past the end
  std::string path = test::writeGltf(dir, s);
  expectInputError([&] { loadGltf(path); },
                   {path, "mesh 'quad' primitive 0", "index 5 is 3", "0..2"});
}

TEST(GltfErrors, WrongAccessorTypes) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["accessors"][1]["type"] = "VEC2";
  std::string path = test::writeGltf(dir, s, "type.gltf");
  expectInputError([&] { loadGltf(path); }, {path, "NORMAL", "type VEC2; expected VEC3"});
  s = test::quadScene(dir);
  s.doc["accessors"][3]["componentType"] = 5126;
  path = test::writeGltf(dir, s, "float-indices.gltf");
  expectInputError([&] { loadGltf(path); }, {path, "indices", "UNSIGNED_BYTE"});
}

TEST(GltfErrors, MissingPositionsAndBadNodes) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  std::string path = test::writeGltf(dir, s, "nopos.gltf");
  expectInputError([&] { loadGltf(path); }, {path, "no POSITION"});
  s = test::quadScene(dir);
  s.doc["nodes"][2]["matrix"] = {1, 0, 0};
  path = test::writeGltf(dir, s, "matrix.gltf");
  expectInputError([&] { loadGltf(path); }, {path, "node 2 matrix has 3 numbers; expected 16"});
  s = test::quadScene(dir);
  s.doc["nodes"][3]["children"] = {0};  // node 0 reached twice
  path = test::writeGltf(dir, s, "cycle.gltf");
  expectInputError([&] { loadGltf(path); }, {path, "node 0 is reached twice"});
}

TEST(GltfErrors, MissingExternalFiles) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}, {"uri", "missing.bin"}}};
  std::string path = dir.write("nobin.gltf", s.doc.dump());
  expectInputError([&] { loadGltf(path); }, {path, "missing.bin"});
}

// A missing image is no missing buffer: as Blender, assimp's viewer and three.js, the model
// loads with one warning naming it, and the material that used it goes without.
TEST(GltfReader, AMissingImageIsLeftOutWithAWarning) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  const size_t textures = loadGltf(test::writeGltf(dir, s, "all.gltf")).textures.size();
  s = test::quadScene(dir);
  s.doc["images"][1]["uri"] = "nowhere.png";
  const std::string path = test::writeGltf(dir, s, "noimage.gltf");
  test::LogCapture log;
  const LoadedModel m = loadGltf(path);
  EXPECT_EQ(m.textures.size(), textures - 1);
  EXPECT_EQ(log.count({"warning", path, "image 1", "nowhere.png", "does not exist"}), 1u);
}

// A uri naming a folder (found by fuzzing: tinygltf opened it and allocated its "size", LLONG_MAX
// on ext4, a bad_alloc) and a buffer past --max-memory are refused before reading.
TEST(GltfErrors, ExternalFilesMustBeRegularFilesWithinTheMemoryCap) {
  TempDir dir;
  std::filesystem::create_directories(dir.file("folder.bin"));
  test::QuadScene s = test::quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}, {"uri", "folder.bin"}}};
  std::string path = dir.write("folder.gltf", s.doc.dump());
  expectInputError([&] { loadGltf(path); }, {path, "folder.bin"});
  s = test::quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}, {"uri", "quad.bin"}}};
  dir.write("quad.bin", s.buffer.data());
  path = dir.write("external.gltf", s.doc.dump());
  EXPECT_EQ(loadGltf(path).meshes.size(), 3u);  // the same buffer as a file is read
  LoadLimits limits;
  limits.max_bytes = s.buffer.data().size() - 1;
  expectInputError([&] { loadGltf(path, limits); }, {path, "quad.bin", "--max-memory"});
}

TEST(GltfErrors, EmptyForeignAndTruncatedFiles) {
  TempDir dir;
  std::string empty = dir.write("empty.gltf", "");
  expectInputError([&] { loadGltf(empty); }, {empty, "empty file"});
  std::string text = dir.write("text.gltf", "solid cube\nendsolid\n");
  expectInputError([&] { loadGltf(text); }, {text});
  test::QuadScene s = test::quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}}};
  std::string bytes = test::glb(s.doc, s.buffer.data());
  std::string cut = dir.write("cut.glb", bytes.substr(0, bytes.size() - 40));
  expectInputError([&] { loadGltf(cut); }, {cut});
  std::string json_cut = dir.write("cut.gltf", s.doc.dump().substr(0, 100));
  expectInputError([&] { loadGltf(json_cut); }, {json_cut});
}

TEST(GltfErrors, UnknownRequiredExtensionGoesToAssimpAndIsNamed) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["extensionsRequired"] = {"EXT_made_up"};
  s.doc["extensionsUsed"] = {"EXT_made_up"};
  std::string path = test::writeGltf(dir, s);
  // Assimp may read the file anyway (it ignores what it does not know) or fail; if it fails, the
  // message names the file and the extension.
  try {
    LoadedModel m = loadGltf(path);
    EXPECT_EQ(m.meshes.size(), 3u);
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find("EXT_made_up"), std::string::npos) << msg;
  }
}

TEST(GltfErrors, LimitsHoldBeforeReading) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  std::string path = test::writeGltf(dir, s);
  LoadLimits limits;
  limits.max_vertices = 7;  // the first placed quad fits, the instance not
  expectInputError([&] { loadGltf(path, limits); }, {path, "8 vertices", "max_vertices"});
  limits.max_vertices = 3;  // not even the first: refused from the accessor's count
  expectInputError([&] { loadGltf(path, limits); }, {path, "POSITION", "4 elements; at most 3"});
  limits = LoadLimits{};
  limits.max_triangles = 3;
  expectInputError([&] { loadGltf(path, limits); }, {path, "max_triangles"});
}

// Truncations and byte flips of a .glb give a model or an InputError, never a crash.
TEST(GltfErrors, SurvivesTruncationsAndByteFlips) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}}};
  const std::string file = test::glb(s.doc, s.buffer.data());
  const std::string path = dir.file("mutant.glb");
  int models = 0, errors = 0;
  auto attempt = [&](const std::string& bytes) {
    dir.write("mutant.glb", bytes);
    try {
      LoadedModel m = loadGltf(path);
      for (const Mesh& mesh : m.meshes) mesh.validate();
      ++models;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(path), std::string::npos) << err.what();
      ++errors;
    }
  };
  for (size_t n = 0; n < file.size(); n += 13) attempt(file.substr(0, n));
  // The binary chunk: counts, offsets and indices are all read from here.
  size_t bin = file.size() - s.buffer.data().size();
  for (size_t i = bin; i < file.size(); ++i) {
    std::string m = file;
    m[i] = char(m[i] ^ 0x40);
    attempt(m);
  }
  // The JSON's digits: counts, offsets, strides and indices.
  for (size_t i = 20; i < bin; ++i) {
    if (file[i] < '0' || file[i] > '9') continue;
    std::string m = file;
    m[i] = file[i] == '9' ? '0' : char(file[i] + 1);
    attempt(m);
  }
  EXPECT_GT(models, 0);
  EXPECT_GT(errors, 0);
}

}  // namespace
}  // namespace mirage
