// glTF files for the tests, built in memory: a binary buffer with aligned views, base64 data
// URIs, and the GLB container.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/image.h"
#include "scene/model_loader_files.h"

namespace mirage::test {

inline std::string base64(const std::string& in) {
  static const char* kChars = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    uint32_t v =
        uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8 | uint8_t(in[i + 2]);
    for (int k = 3; k >= 0; --k) out += kChars[(v >> (6 * k)) & 63];
  }
  if (i + 1 == in.size()) {
    uint32_t v = uint32_t(uint8_t(in[i])) << 16;
    out += std::string{kChars[v >> 18], kChars[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == in.size()) {
    uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8;
    out += std::string{kChars[v >> 18], kChars[(v >> 12) & 63], kChars[(v >> 6) & 63], '='};
  }
  return out;
}

// Appends values to a little-endian buffer, each run 4-byte aligned; returns the run's offset.
class GltfBuffer {
 public:
  template <typename T>
  size_t add(const std::vector<T>& values) {
    while (data_.size() % 4) data_ += '\0';
    size_t offset = data_.size();
    data_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    return offset;
  }
  const std::string& data() const { return data_; }
  std::string dataUri() const { return "data:application/octet-stream;base64," + base64(data_); }

 private:
  std::string data_;
};

// A GLB container: the JSON chunk and, when `bin` is not empty, the BIN chunk.
inline std::string glb(const nlohmann::json& json, std::string bin) {
  std::string text = json.dump();
  while (text.size() % 4) text += ' ';
  while (bin.size() % 4) bin += '\0';
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string out = "glTF" + u32(2) + u32(0) + u32(uint32_t(text.size())) + u32(0x4E4F534A) + text;
  if (!bin.empty()) out += u32(uint32_t(bin.size())) + u32(0x004E4942) + bin;
  std::string total = u32(uint32_t(out.size()));
  std::memcpy(out.data() + 8, total.data(), 4);
  return out;
}

// A PNG of `image` (display values in [0, 1]) as bytes, written through writePng.
inline std::string pngBytes(const TempDir& dir, const Image& image, const std::string& name) {
  std::string path = dir.file(name);
  writePng(path, image);
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A solid-colour image.
inline Image solid(int w, int h, vec4 color) {
  return Image(w, h, color);
}

// The scene written as .gltf with its buffer as a base64 data URI; returns the path.
// A unit quad in z = 0 (two triangles), used by three nodes: a child under a translated root
// (rotated 90 degrees about +Y, scaled 2), an instance placed by a matrix, and a textured copy.
struct QuadScene {
  nlohmann::json doc;
  GltfBuffer buffer;
};

inline QuadScene quadScene(const TempDir& dir, int index_type = 5123) {
  QuadScene s;
  std::vector<float> pos = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  std::vector<float> nrm = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::vector<float> uv = {0, 1, 1, 1, 1, 0, 0, 0};  // glTF: v = 0 is the image's top row
  size_t p = s.buffer.add(pos), n = s.buffer.add(nrm), t = s.buffer.add(uv), i = 0;
  size_t index_bytes = 0;
  if (index_type == 5121) i = s.buffer.add(std::vector<uint8_t>{0, 1, 2, 0, 2, 3}), index_bytes = 6;
  if (index_type == 5123)
    i = s.buffer.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}), index_bytes = 12;
  if (index_type == 5125)
    i = s.buffer.add(std::vector<uint32_t>{0, 1, 2, 0, 2, 3}), index_bytes = 24;
  nlohmann::json prim = {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                         {"indices", 3}};
  nlohmann::json textured = prim;
  prim["material"] = 0;
  textured["material"] = 1;
  std::string albedo_png = pngBytes(dir, solid(2, 2, vec4(0.5f, 0.25f, 1.0f, 1.0f)), "a.png");
  pngBytes(dir, solid(2, 2, vec4(0.5f, 0.5f, 1.0f, 1.0f)), "normal.png");
  s.doc = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 2, 3}}}}},
      {"nodes",
       {{{"name", "root"}, {"translation", {1, 2, 3}}, {"children", {1}}},
        {{"name", "child"},
         {"rotation", {0, 0.70710678, 0, 0.70710678}},
         {"scale", {2, 2, 2}},
         {"mesh", 0}},
        {{"name", "instance"},
         {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 20, 30, 1}},
         {"mesh", 0}},
        {{"name", "tex"}, {"mesh", 1}}}},
      {"meshes",
       {{{"name", "quad"}, {"primitives", {prim}}},
        {{"name", "painted"}, {"primitives", {textured}}}}},
      {"materials",
       {{{"name", "chrome"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.9, 0.8, 0.7, 1}},
           {"metallicFactor", 1},
           {"roughnessFactor", 0}}}},
        {{"name", "paint"},
         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}},
         {"normalTexture", {{"index", 1}}}}}},
      {"textures", {{{"source", 0}}, {{"source", 1}}}},
      {"images",
       {{{"uri", "data:image/png;base64," + base64(albedo_png)}}, {{"uri", "normal.png"}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"byteOffset", p},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 1, 0}}},
        {{"bufferView", 0},
         {"byteOffset", n},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"}},
        {{"bufferView", 0},
         {"byteOffset", t},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC2"}},
        {{"bufferView", 1}, {"componentType", index_type}, {"count", 6}, {"type", "SCALAR"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", i}},
        {{"buffer", 0}, {"byteOffset", i}, {"byteLength", index_bytes}}}},
  };
  return s;
}

inline std::string writeGltf(const TempDir& dir, QuadScene& s,
                             const std::string& name = "quad.gltf") {
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}, {"uri", s.buffer.dataUri()}}};
  return dir.write(name, s.doc.dump(1));
}

}  // namespace mirage::test
