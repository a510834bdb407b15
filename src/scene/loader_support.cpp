#include "scene/loader_support.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <spdlog/spdlog.h>

#include "core/error.h"

namespace mirage::loader {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

std::string lowerExtension(const std::string& path) {
  std::filesystem::path p(path);
  std::string ext = lower(p.extension().string());
  if (ext == ".gz") ext = lower(p.stem().extension().string()) + ext;
  return ext;
}

std::string fileStem(const std::string& path) {
  std::filesystem::path p = std::filesystem::path(path).filename();
  if (lower(p.extension().string()) == ".gz") p = p.stem();
  return p.stem().string();
}

std::string folderOf(const std::string& path) {
  std::string dir = std::filesystem::path(path).parent_path().string();
  return dir.empty() ? dir : dir + "/";
}

std::string readWholeFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throwInput("{}: is a folder, not a file", path);
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throwInput("{}: cannot read the file: {}", path, std::strerror(errno));
  std::string out;
  uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec) out.resize(size_t(size));
  size_t got = std::fread(out.data(), 1, out.size(), f.get());
  out.resize(got);
  // Files that grew meanwhile, or whose size the file system does not know (pipes): read on.
  char buffer[65536];
  while (size_t n = std::fread(buffer, 1, sizeof(buffer), f.get())) out.append(buffer, n);
  if (std::ferror(f.get())) throwInput("{}: I/O error while reading the file", path);
  return out;
}

void checkLimits(const std::string& file, const std::string& what, uint64_t vertices,
                 uint64_t triangles, const LoadLimits& limits) {
  if (vertices > limits.max_vertices)
    throwInput("{}: {} has {} vertices; at most {} are allowed (LoadLimits::max_vertices)", file,
               what, vertices, limits.max_vertices);
  if (triangles > limits.max_triangles)
    throwInput("{}: {} has {} triangles; at most {} are allowed (LoadLimits::max_triangles)", file,
               what, triangles, limits.max_triangles);
  checkAllocation(file, fmt::format("{} ({} vertices, {} triangles)", what, vertices, triangles),
                  meshBytes(vertices, triangles), limits.max_bytes);
}

uint64_t meshBytes(uint64_t vertices, uint64_t triangles) {
  return saturatingMul(saturatingAdd(saturatingMul(vertices, 48), saturatingMul(triangles, 12)), 2);
}

int TextureList::get(const std::string& key, Encoding encoding,
                     const std::function<Image()>& decode) {
  auto [it, inserted] = index_.try_emplace({key, encoding}, int(textures_.size()));
  if (!inserted) return it->second;
  try {
    TextureImage t;
    t.name = key;
    t.image = decode();
    t.srgb = encoding == Encoding::kSrgb;
    textures_.push_back(std::move(t));
  } catch (...) {
    index_.erase(it);
    throw;
  }
  return it->second;
}

std::string textureFile(const std::string& folder, std::string name) {
  std::replace(name.begin(), name.end(), '\\', '/');
  const std::filesystem::path given(name);
  std::error_code ec;
  const std::string as_given = given.is_absolute() ? name : folder + name;
  if (std::filesystem::is_regular_file(as_given, ec)) return as_given;
  const std::string alone = folder + given.filename().string();
  if (given.has_filename() && std::filesystem::is_regular_file(alone, ec)) {
    spdlog::warn("texture {} not found where named; using {}", name, alone);
    return alone;
  }
  return {};
}

int TextureList::missing(const std::string& where, const std::string& file) {
  if (missing_.insert(file).second)
    spdlog::warn("{}: texture file {} does not exist; drawn without that texture", where, file);
  return -1;
}

LoadedModel singleMeshModel(Mesh mesh) {
  LoadedModel model;
  model.meshes.push_back(std::move(mesh));
  model.mesh_material.push_back(-1);
  model.mesh_transform.push_back(mat4(1.0f));
  return model;
}

namespace {

// `v` made unit length; InputError naming `what` and `field` when it has none.
vec3 unitAfterTransform(const std::string& what, const char* field, vec3 v) {
  const float len = glm::length(v);
  if (!(len > 0.0f) || !std::isfinite(len))
    throwInput("{}: its node's transform makes its {} {} (a scale of 0, or overflow)", what, field,
               std::isfinite(len) ? "zero" : "not finite");
  return v / len;
}

}  // namespace

CameraDesc placedCamera(const std::string& what, const mat4& world, vec3 eye, vec3 forward,
                        vec3 up) {
  CameraDesc c;
  c.position = transformPoint(world, eye);
  if (!isFinite(c.position)) throwInput("{}: its node's transform puts it at infinity", what);
  const vec3 f = unitAfterTransform(what, "view direction", mat3(world) * forward);
  c.up = unitAfterTransform(what, "up direction", mat3(world) * up);
  // A shearing transform can fold up onto the view direction; a view needs them apart.
  if (!(glm::length(glm::cross(f, c.up)) > 1e-6f))
    throwInput("{}: its node's transform makes its up direction parallel to its view direction",
               what);
  c.target = c.position + f;
  return c;
}

vec3 placedLightDirection(const std::string& what, const mat4& world, vec3 shine) {
  return -unitAfterTransform(what, "direction", mat3(world) * shine);
}

std::string uniqueName(const std::string& name, std::set<std::string>& taken) {
  std::string out = name;
  for (int k = 2; taken.count(out); ++k) out = fmt::format("{}-{}", name, k);
  taken.insert(out);
  return out;
}

void uniqueCameraNames(const std::string& file, std::vector<CameraDesc>& cameras,
                       std::set<std::string> taken) {
  for (CameraDesc& c : cameras) {
    const std::string name = uniqueName(c.name, taken);
    if (name != c.name)
      spdlog::warn("{}: a second camera named '{}' is called '{}'", file, c.name, name);
    c.name = name;
  }
}

bool repairNormals(Mesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size()) {
    mesh.computeNormals();
    return true;
  }
  for (vec3& n : mesh.normals) {
    float len = glm::length(n);
    if (!(len > 0.0f) || !std::isfinite(len)) {
      mesh.computeNormals();
      return true;
    }
    n /= len;
  }
  return false;
}

}  // namespace mirage::loader
