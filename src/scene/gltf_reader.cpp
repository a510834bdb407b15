// glTF 2.0 (.gltf with external or base64 buffers, .glb) through tinygltf (mirage's own copy,
// see gltf_model.h). tinygltf has no Draco here: files that require an extension
// (KHR_draco_mesh_compression, EXT_meshopt_compression, ...) are handed to assimp, which reads
// Draco (and fails clearly on what it cannot read).
//
// Conventions: glTF texture coordinates have their origin at the image's top-left, mirage's (like
// OBJ's and assimp's) at the bottom-left, so v becomes 1 - v. TANGENT is kept as stored: its w
// already points the bitangent at the image's "up" (+Y of glTF normal maps), which is +v after the
// flip. Materials: pbrMetallicRoughness metallicFactor 1 and roughnessFactor 0 make a reflector
// tinted by baseColorFactor over a 0.05 grey base (a perfect metal mirror's base colour only
// shows past the last reflection order); anything else is diffuse with baseColorFactor times
// baseColorTexture. Cameras and the KHR_lights_punctual light: gltf_scene_parts.h.
#include <cstring>
#include <filesystem>
#include <numeric>
#include <optional>

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/memory_cap.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_scene_parts.h"
#include "scene/loader_support.h"
#include "scene/model_loader.h"

namespace mirage {

namespace {

// tinygltf would decode images to 8-bit RGBA itself; keep the encoded bytes instead so that
// readImageFromMemory decodes them with the right encoding (sRGB colour, linear normal maps).
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->width = image->height = image->component = -1;
  return true;
}

// The glTF extensions the file requires, read from its JSON before tinygltf parses it: tinygltf
// cannot even parse Draco-compressed primitives (their accessors have no bufferView).
std::vector<std::string> requiredExtensions(const std::string& bytes) {
  std::string_view json = bytes;
  if (bytes.starts_with("glTF")) {
    // GLB: 12-byte header, then the JSON chunk (length, type "JSON", data).
    if (bytes.size() < 20) return {};
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    json = json.substr(20, std::min<size_t>(length, bytes.size() - 20));
  }
  if (json.find("\"extensionsRequired\"") == std::string_view::npos) return {};
  nlohmann::json doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
  std::vector<std::string> out;
  if (doc.is_object() && doc.contains("extensionsRequired") && doc["extensionsRequired"].is_array())
    for (const auto& e : doc["extensionsRequired"])
      if (e.is_string()) out.push_back(e.get<std::string>());
  return out;
}

// tinygltf's own file callbacks open a buffer's or an image's uri with an ifstream and allocate
// the size seekg/tellg report: a uri naming a folder opens, and its "size" (LLONG_MAX on ext4)
// threw std::bad_alloc (found by fuzzing); nor do they know --max-memory. These read regular files
// only, after holding their size to the limits (user_data: the LoadLimits).
bool isRegularFile(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string unexpandedPath(const std::string& path, void*) {
  return path;
}

bool readExternalFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                      void* limits) {
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || !std::filesystem::is_regular_file(path, ec)) {
    *err += path + ": not a readable file";
    return false;
  }
  try {  // tinygltf adds the message to its own, which names the glTF file's field
    checkAllocation(path, "reading the file", size,
                    static_cast<const LoadLimits*>(limits)->max_bytes);
    const std::string bytes = loader::readWholeFile(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    *err += e.what();
    return false;
  }
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

class GltfConverter {
 public:
  GltfConverter(const std::string& path, const tinygltf::Model& model, const LoadLimits& limits)
      : path_(path), gltf_(model), limits_(limits), textures_(out_.textures) {}

  LoadedModel run() {
    for (size_t i = 0; i < gltf_.materials.size(); ++i) out_.materials.push_back(material(int(i)));
    // Depth-first, in file order (the stack gets children in reverse).
    std::vector<std::pair<int, mat4>> stack;
    std::vector<int> r = roots();
    for (auto it = r.rbegin(); it != r.rend(); ++it) stack.push_back({*it, mat4(1.0f)});
    if (stack.empty())  // meshes without nodes: show each once, untransformed
      for (size_t m = 0; m < gltf_.meshes.size(); ++m) addMesh(int(m), mat4(1.0f), "");
    gltf::SceneParts parts(path_, gltf_);
    std::vector<char> seen(gltf_.nodes.size(), 0);
    while (!stack.empty()) {
      auto [n, parent] = stack.back();
      stack.pop_back();
      if (n < 0 || size_t(n) >= gltf_.nodes.size())
        throwInput("{}: node {} does not exist (the file has {})", path_, n, gltf_.nodes.size());
      if (seen[size_t(n)]++)
        throwInput("{}: node {} is reached twice; glTF nodes must form trees", path_, n);
      const tinygltf::Node& node = gltf_.nodes[size_t(n)];
      mat4 world = parent * localMatrix(n, node);
      if (node.mesh >= 0) addMesh(node.mesh, world, node.name);
      parts.addNode(n, node, world);
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
        stack.push_back({*c, world});
    }
    if (out_.meshes.empty()) throwInput("{}: the glTF file has no triangle meshes", path_);
    parts.finish(out_);
    return std::move(out_);
  }

 private:
  std::vector<int> roots() const {
    if (!gltf_.scenes.empty()) {
      int s = gltf_.defaultScene >= 0 && size_t(gltf_.defaultScene) < gltf_.scenes.size()
                  ? gltf_.defaultScene
                  : 0;
      return gltf_.scenes[size_t(s)].nodes;
    }
    std::vector<char> child(gltf_.nodes.size(), 0);
    for (const tinygltf::Node& n : gltf_.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = 1;
    std::vector<int> r;
    for (size_t i = 0; i < gltf_.nodes.size(); ++i)
      if (!child[i]) r.push_back(int(i));
    return r;
  }

  mat4 localMatrix(int index, const tinygltf::Node& n) const {
    auto check = [&](const std::vector<double>& v, size_t size, const char* what) {
      if (!v.empty() && v.size() != size)
        throwInput("{}: node {} {} has {} numbers; expected {}", path_, index, what, v.size(),
                   size);
      for (double d : v)
        if (!std::isfinite(d)) throwInput("{}: node {} {} is not finite", path_, index, what);
    };
    check(n.matrix, 16, "matrix");
    check(n.translation, 3, "translation");
    check(n.rotation, 4, "rotation");
    check(n.scale, 3, "scale");
    mat4 m(1.0f);
    if (!n.matrix.empty()) {
      for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = float(n.matrix[size_t(i)]);  // column-major
      return m;
    }
    if (!n.translation.empty())
      m = glm::translate(m, vec3(n.translation[0], n.translation[1], n.translation[2]));
    if (!n.rotation.empty()) {
      quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]),
             float(n.rotation[2]));
      if (glm::length(q) > 0.0f) m *= glm::mat4_cast(glm::normalize(q));
    }
    if (!n.scale.empty()) m = glm::scale(m, vec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
  }

  void addMesh(int index, const mat4& world, const std::string& node) {
    if (index < 0 || size_t(index) >= gltf_.meshes.size())
      throwInput("{}: a node refers to mesh {}, but the file has {}", path_, index,
                 gltf_.meshes.size());
    const tinygltf::Mesh& mesh = gltf_.meshes[size_t(index)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      auto key = std::make_pair(index, int(p));
      auto it = converted_.find(key);
      std::optional<Mesh> m;
      if (it == converted_.end()) {
        m = primitive(mesh, index, int(p));
        converted_[key] = m ? int(out_.meshes.size()) : -1;
      } else if (it->second >= 0) {
        m = out_.meshes[size_t(it->second)];  // a mesh used by several nodes: one copy each
        budget(*m);
      }
      if (!m) continue;
      int material = mesh.primitives[p].material;
      out_.meshes.push_back(std::move(*m));
      out_.mesh_material.push_back(
          material >= 0 && size_t(material) < gltf_.materials.size() ? material : -1);
      out_.mesh_transform.push_back(world);
      out_.mesh_node.push_back(node);
    }
  }

  void budget(const Mesh& m) {
    vertices_ += m.positions.size();
    triangles_ += m.triangles.size();
    loader::checkLimits(path_, "the file", vertices_, triangles_, limits_);
  }

  std::optional<Mesh> primitive(const tinygltf::Mesh& mesh, int mi, int pi) {
    const tinygltf::Primitive& prim = mesh.primitives[size_t(pi)];
    std::string name = mesh.name.empty() ? fmt::format("mesh{}", mi) : mesh.name;
    if (mesh.primitives.size() > 1) name += fmt::format("/{}", pi);
    std::string what = fmt::format("mesh '{}' primitive {}", name, pi);
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      spdlog::warn("{}: {} has mode {} (points or lines); skipped", path_, what, prim.mode);
      return std::nullopt;
    }
    Mesh m;
    m.name = name;
    m.source = path_;
    readVertices(prim, what, m);
    const std::vector<uint32_t> idx = readIndices(prim, what, m.positions.size());
    if (prim.mode == TINYGLTF_MODE_TRIANGLES && idx.size() % 3 != 0)
      throwInput("{}: {} has {} indices, not a multiple of 3 (mode TRIANGLES)", path_, what,
                 idx.size());
    appendTriangles(prim.mode, idx, m.triangles);
    if (m.triangles.empty()) {
      spdlog::warn("{}: {} has no triangles; skipped", path_, what);
      return std::nullopt;
    }
    if (m.normals.empty())
      m.computeNormals();
    else
      loader::repairNormals(m);
    bool normal_map = prim.material >= 0 && size_t(prim.material) < out_.materials.size() &&
                      out_.materials[size_t(prim.material)].normal_map >= 0;
    if (normal_map && m.tangents.empty() && !m.uvs.empty()) m.computeTangents();
    budget(m);
    return m;
  }

  static int attributeOf(const tinygltf::Primitive& prim, const char* name) {
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
  }

  // The primitive's positions, and its normals, texture coordinates and tangents where given,
  // each as many as the positions.
  void readVertices(const tinygltf::Primitive& prim, const std::string& what, Mesh& m) {
    int position = attributeOf(prim, "POSITION");
    if (position < 0) throwInput("{}: {} has no POSITION attribute", path_, what);
    const uint64_t vertex_budget = limits_.max_vertices - std::min(limits_.max_vertices, vertices_);
    auto read = [&](int accessor, int comps, bool normalized, const char* a) {
      return gltf::readFloats(gltf_, accessor, comps, normalized, vertex_budget,
                              gltf::Use{path_, what + " " + a});
    };
    std::vector<float> p = read(position, 3, false, "POSITION");
    size_t n = p.size() / 3;
    m.positions.resize(n);
    for (size_t i = 0; i < n; ++i) {
      m.positions[i] = vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
      if (!isFinite(m.positions[i])) throwInput("{}: {} POSITION {} is not finite", path_, what, i);
    }
    auto sameCount = [&](const std::vector<float>& v, int comps, const char* a) {
      if (v.size() != n * size_t(comps))
        throwInput("{}: {} {} has {} elements; POSITION has {}", path_, what, a,
                   v.size() / size_t(comps), n);
    };
    if (int a = attributeOf(prim, "NORMAL"); a >= 0) {
      std::vector<float> v = read(a, 3, false, "NORMAL");
      sameCount(v, 3, "NORMAL");
      m.normals.resize(n);
      for (size_t i = 0; i < n; ++i) m.normals[i] = vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    }
    if (int a = attributeOf(prim, "TEXCOORD_0"); a >= 0) {
      std::vector<float> v = read(a, 2, true, "TEXCOORD_0");
      sameCount(v, 2, "TEXCOORD_0");
      m.uvs.resize(n);
      for (size_t i = 0; i < n; ++i) m.uvs[i] = vec2(v[2 * i], 1.0f - v[2 * i + 1]);
    }
    if (int a = attributeOf(prim, "TANGENT"); a >= 0 && !m.uvs.empty()) {
      std::vector<float> v = read(a, 4, false, "TANGENT");
      sameCount(v, 4, "TANGENT");
      m.tangents.resize(n);
      for (size_t i = 0; i < n; ++i) {
        vec3 t(v[4 * i], v[4 * i + 1], v[4 * i + 2]);
        float len = glm::length(t);
        m.tangents[i] = vec4(len > 0.0f && std::isfinite(len) ? t / len : vec3(1, 0, 0),
                             v[4 * i + 3] < 0.0f ? -1.0f : 1.0f);
      }
    }
  }

  // The primitive's indices, each checked against the n vertices, or 0..n-1 when it has none.
  std::vector<uint32_t> readIndices(const tinygltf::Primitive& prim, const std::string& what,
                                    size_t n) {
    std::vector<uint32_t> idx;
    if (prim.indices < 0) {
      idx.resize(n);
      std::iota(idx.begin(), idx.end(), 0u);
      return idx;
    }
    const uint64_t index_budget =
        3 * (limits_.max_triangles - std::min(limits_.max_triangles, triangles_)) + 2;
    idx = gltf::readIndices(gltf_, prim.indices, index_budget, gltf::Use{path_, what + " indices"});
    for (size_t i = 0; i < idx.size(); ++i)
      if (idx[i] >= n)
        throwInput("{}: {} index {} is {}, outside 0..{} (POSITION has {} elements)", path_, what,
                   i, idx[i], int64_t(n) - 1, n);
    return idx;
  }

  // The triangles of a TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN index list.
  static void appendTriangles(int mode, const std::vector<uint32_t>& idx,
                              std::vector<uvec3>& triangles) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (size_t i = 0; i + 2 < idx.size(); i += 3)
        triangles.push_back({idx[i], idx[i + 1], idx[i + 2]});
      return;
    }
    bool strip = mode == TINYGLTF_MODE_TRIANGLE_STRIP;
    for (size_t i = 2; i < idx.size(); ++i) {
      if (!strip)
        triangles.push_back({idx[0], idx[i - 1], idx[i]});
      else if (i % 2 == 0)
        triangles.push_back({idx[i - 2], idx[i - 1], idx[i]});
      else
        triangles.push_back({idx[i - 1], idx[i - 2], idx[i]});
    }
  }

  Material material(int index) {
    const tinygltf::Material& g = gltf_.materials[size_t(index)];
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    std::string name = g.name.empty() ? fmt::format("material{}", index) : g.name;
    vec3 color(1.0f);
    if (pbr.baseColorFactor.size() >= 3)
      color = vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
    Material m;
    if (pbr.metallicFactor == 1.0 && pbr.roughnessFactor == 0.0) {
      m = Material::mirror(name, vec3(0.05f), color);
    } else {
      m = Material::diffuse(name, color);
      m.albedo_texture =
          texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, Encoding::kSrgb, name);
    }
    m.normal_map =
        texture(g.normalTexture.index, g.normalTexture.texCoord, Encoding::kLinear, name);
    return m;
  }

  int texture(int index, int tex_coord, Encoding encoding, const std::string& material) {
    if (index < 0) return -1;
    if (size_t(index) >= gltf_.textures.size())
      throwInput("{}: material {} refers to texture {}, but the file has {}", path_, material,
                 index, gltf_.textures.size());
    if (tex_coord != 0)
      spdlog::warn("{}: material {} uses TEXCOORD_{}; mirage reads TEXCOORD_0", path_, material,
                   tex_coord);
    int source = gltf_.textures[size_t(index)].source;
    if (source < 0) {
      spdlog::warn("{}: texture {} has no PNG/JPEG source (an extension's format?); ignored", path_,
                   index);
      return -1;
    }
    if (size_t(source) >= gltf_.images.size())
      throwInput("{}: texture {} refers to image {}, but the file has {}", path_, index, source,
                 gltf_.images.size());
    const tinygltf::Image& img = gltf_.images[size_t(source)];
    std::string key = img.uri.empty() || img.uri.starts_with("data:")
                          ? fmt::format("{}#image{}", path_, source)
                          : loader::folderOf(path_) + img.uri;
    // An external image whose file does not exist: tinygltf warned and left it empty.
    if (img.image.empty() && !img.uri.empty() && !img.uri.starts_with("data:") &&
        !std::filesystem::is_regular_file(key))
      return textures_.missing(fmt::format("{}: image {}", path_, source), key);
    return textures_.get(key, encoding, [&] {
      if (img.image.empty())
        throwInput("{}: image {} ('{}') could not be read", path_, source, img.uri);
      return readImageFromMemory(key, img.image.data(), img.image.size(), encoding);
    });
  }

  const std::string& path_;
  const tinygltf::Model& gltf_;
  const LoadLimits& limits_;
  LoadedModel out_;
  loader::TextureList textures_;
  std::map<std::pair<int, int>, int> converted_;  // (mesh, primitive) -> index in out_.meshes
  uint64_t vertices_ = 0, triangles_ = 0;
};

}  // namespace

LoadedModel loadGltf(const std::string& path, const LoadLimits& limits) {
  return readGltf(path, loader::readWholeFile(path), limits);
}

LoadedModel readGltf(const std::string& path, const std::string& bytes, const LoadLimits& limits) {
  if (bytes.empty()) throwInput("{}: empty file (expected glTF JSON or a GLB container)", path);
  if (bytes.size() >= (uint64_t(1) << 32)) throwInput("{}: larger than 4 GiB", path);
  if (std::vector<std::string> required = requiredExtensions(bytes); !required.empty()) {
    std::string list = fmt::format("{}", fmt::join(required, ", "));
    spdlog::info("{}: requires {}, which tinygltf lacks; reading it with assimp", path, list);
    try {
      return loadWithAssimp(path, limits);
    } catch (const InputError& e) {
      throwInput("{} (the file requires the glTF extensions {})", e.what(), list);
    }
  }
  tinygltf::Model model;
  tinygltf::TinyGLTF ctx;
  ctx.SetImageLoader(&keepEncodedImage, nullptr);
  ctx.SetFsCallbacks({&isRegularFile, &unexpandedPath, &readExternalFile, nullptr,
                      const_cast<LoadLimits*>(&limits)});
  std::string err, warn, base = loader::folderOf(path);
  bool ok = bytes.starts_with("glTF")
                ? ctx.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           unsigned(bytes.size()), base)
                : ctx.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()),
                                          base);
  if (!ok) throwInput("{}: {}", path, err.empty() ? "not a readable glTF file" : trimmed(err));
  if (!warn.empty()) spdlog::warn("{}: {}", path, trimmed(warn));
  return GltfConverter(path, model, limits).run();
}

}  // namespace mirage
