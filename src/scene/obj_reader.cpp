// Wavefront OBJ through tinyobjloader, with the .mtl materials.
//
// Grouping: one Mesh per (shape, material) pair — each `o`/`g` shape is split by its `usemtl`
// materials. Shapes stay apart because every reflector needs its own mesh (envmap captures a
// probe at the centre of each reflector's bounds: two mirrors merged into one mesh would share a
// probe between them), and a mesh can carry only one material.
//
// Reflectors (OBJ has no mirror flag; these are the MTL conventions that mean one):
//   illum 3 ("reflection on, ray trace on")   perfect mirror: base Kd, tint Ks, f0 1
//   illum 5 ("Fresnel on, ray trace on")      Fresnel mirror: base Kd, f0 max(Ks), tint Ks / f0
//   Ks >= 0.95, Ns >= 1000 and Kd <= 0.05     perfect mirror (exporters' mirrors without illum)
//   Pm 1 and Pr 0 (the PBR extension)         perfect mirror as in glTF: base 0.05 grey, tint Kd
// A black Ks gives a white tint: "illum 3" alone means a plain mirror.
// Everything else is diffuse: albedo Kd times map_Kd (sRGB). map_bump/bump/norm -> normal map.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <spdlog/spdlog.h>
#include <tiny_obj_loader.h>

#include "core/error.h"
#include "scene/loader_support.h"
#include "scene/model_loader.h"

namespace mirage {

namespace {

// Reads each mtllib file beside the .obj and remembers which file each material came from (for
// messages and for resolving texture paths).
class MtlReader : public tinyobj::MaterialReader {
 public:
  MtlReader(std::string folder, std::vector<std::string>& mtl_of)
      : folder_(std::move(folder)), mtl_of_(mtl_of) {}
  bool operator()(const std::string& file, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warn, std::string* err) override {
    std::string path = std::filesystem::path(file).is_absolute() ? file : folder_ + file;
    std::ifstream in(path);
    if (!in) {
      if (warn) *warn += fmt::format("material file {} not found; default materials used\n", path);
      return false;
    }
    tinyobj::LoadMtl(names, materials, &in, warn, err);
    mtl_of_.resize(materials->size(), path);
    return true;
  }

 private:
  std::string folder_;
  std::vector<std::string>& mtl_of_;
};

// A `v` line's words other than numbers ("nan", "inf"), which tinyobjloader would read as 0.
bool hasNonNumber(const std::string& text, size_t begin, size_t end) {
  for (size_t k = begin; k < end && text[k] != '#'; ++k)
    if (std::isalpha(static_cast<unsigned char>(text[k])) && text[k] != 'e' && text[k] != 'E')
      return true;
  return false;
}

// Counts `v` and `f` lines without parsing them, to hold the limits before tinyobjloader
// allocates anything, and refuses positions that are not numbers.
void preScan(const std::string& path, const std::string& text, const LoadLimits& limits) {
  uint64_t v = 0, f = 0, line = 1;
  for (size_t pos = 0; pos < text.size(); ++line) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    size_t i = text.find_first_not_of(" \t", pos);
    if (i < eol && i + 1 < eol && (text[i + 1] == ' ' || text[i + 1] == '\t')) {
      if (text[i] == 'v') {
        ++v;
        if (hasNonNumber(text, i + 2, eol))
          throwInput(
              "{}: line {}: vertex {} has a non-finite position ('{}'); positions must be "
              "finite numbers",
              path, line, v, text.substr(i, std::min<size_t>(eol - i, 80)));
      }
      if (text[i] == 'f') ++f;
    }
    pos = eol + 1;
  }
  loader::checkLimits(path, "the file", v, f, limits);
}

struct Corner {
  int v, n, t;
  bool operator==(const Corner&) const = default;
};
struct CornerHash {
  size_t operator()(const Corner& c) const {
    uint64_t h = uint64_t(uint32_t(c.v)) * 0x9E3779B97F4A7C15ull;
    h ^= uint64_t(uint32_t(c.n)) * 0xC2B2AE3D27D4EB4Full + (h >> 29);
    h ^= uint64_t(uint32_t(c.t)) * 0x165667B19E3779F9ull + (h >> 32);
    return size_t(h);
  }
};

// One mesh under construction: the corners seen so far, de-duplicated by their index triple.
struct Group {
  int material = -1;
  Mesh mesh;
  std::unordered_map<Corner, uint32_t, CornerHash> index;
  bool all_normals = true, any_uv = false;
};

float maxOf(const float* c) {
  return std::max({c[0], c[1], c[2]});
}
float minOf(const float* c) {
  return std::min({c[0], c[1], c[2]});
}

class ObjMaterials {
 public:
  ObjMaterials(const std::string& obj, const std::vector<std::string>& mtl_of, LoadedModel& model)
      : obj_(obj), mtl_of_(mtl_of), textures_(model.textures) {}

  Material convert(size_t index, const tinyobj::material_t& t) {
    const std::string& mtl = index < mtl_of_.size() ? mtl_of_[index] : obj_;
    Material m = Material::diffuse(t.name, vec3(0.8f));
    vec3 kd(t.diffuse[0], t.diffuse[1], t.diffuse[2]);
    vec3 ks(t.specular[0], t.specular[1], t.specular[2]);
    const float ks_max = maxOf(t.specular);
    bool illum_mirror = t.illum == 3 || t.illum == 5;
    bool exported_mirror =
        minOf(t.specular) >= 0.95f && t.shininess >= 1000.0f && maxOf(t.diffuse) <= 0.05f;
    bool pbr_mirror = t.metallic >= 1.0f && t.roughness <= 0.0f;
    if (illum_mirror || exported_mirror) {
      m = Material::mirror(t.name, kd, ks_max > 0.0f ? ks : vec3(1.0f));
      if (t.illum == 5 && ks_max > 0.0f) {
        m.fresnel_f0 = std::min(1.0f, ks_max);
        m.tint = ks / ks_max;
      }
    } else if (pbr_mirror) {
      m = Material::mirror(t.name, vec3(0.05f), kd);  // as for glTF: the colour tints the mirror
    } else {
      m.albedo = kd;
      if (!t.diffuse_texname.empty())
        m.albedo_texture = texture(mtl, t.name, "map_Kd", t.diffuse_texname, Encoding::kSrgb);
    }
    const std::string& normal = !t.normal_texname.empty() ? t.normal_texname : t.bump_texname;
    if (!normal.empty())
      m.normal_map = texture(mtl, t.name, t.normal_texname.empty() ? "map_bump" : "norm", normal,
                             Encoding::kLinear);
    return m;
  }

 private:
  int texture(const std::string& mtl, const std::string& material, const char* key,
              std::string name, Encoding encoding) {
    const std::string path = loader::textureFile(loader::folderOf(mtl), name);
    if (path.empty())
      return textures_.missing(
          fmt::format("{}: material {} {} (the materials of {})", mtl, material, key, obj_), name);
    return textures_.get(path, encoding, [&] {
      try {
        return readImage(path, encoding);
      } catch (const InputError& e) {
        throwInput("{}: material {} {}: {}", mtl, material, key, e.what());
      }
    });
  }

  const std::string& obj_;
  const std::vector<std::string>& mtl_of_;
  loader::TextureList textures_;
};

// What tinyobjloader reads of a file, and the .mtl file each material came from.
struct ObjFile {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::vector<std::string> mtl_of;
};

ObjFile parseObj(const std::string& path, std::string text) {
  ObjFile obj;
  MtlReader mtl_reader(loader::folderOf(path), obj.mtl_of);
  std::string warn, err;
  bool ok;
  {
    std::istringstream in(std::move(text));
    ok = tinyobj::LoadObj(&obj.attrib, &obj.shapes, &obj.materials, &warn, &err, &in, &mtl_reader,
                          /*triangulate=*/false, /*default_vcols_fallback=*/false);
  }
  if (!ok || !err.empty()) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throwInput("{}: {}", path, err.empty() ? "not a readable OBJ file" : err);
  }
  // Out-of-bounds indices are reported by addCorner as errors, with the face.
  std::istringstream warnings(warn);
  for (std::string line; std::getline(warnings, line);)
    if (!line.empty() && line.find("out of bounds") == std::string::npos)
      spdlog::warn("{}: {}", path, line);
  return obj;
}

// A shape's faces split into one group per material, corners de-duplicated within a group.
class ShapeSplitter {
 public:
  ShapeSplitter(const std::string& path, const ObjFile& obj, const LoadLimits& limits)
      : path_(path),
        obj_(obj),
        limits_(limits),
        nv_(int(obj.attrib.vertices.size() / 3)),
        nn_(int(obj.attrib.normals.size() / 3)),
        nt_(int(obj.attrib.texcoords.size() / 2)) {}

  std::vector<Group> split(size_t s) {
    const tinyobj::mesh_t& sm = obj_.shapes[s].mesh;
    std::vector<Group> groups;
    std::unordered_map<int, size_t> group_of;
    size_t first = 0;
    for (size_t f = 0; f < sm.num_face_vertices.size(); first += sm.num_face_vertices[f], ++f) {
      size_t n = sm.num_face_vertices[f];
      if (first + n > sm.indices.size())
        throwInput("{}: shape {} face {} has corners past the index list", path_, s, f);
      int mat = f < sm.material_ids.size() ? sm.material_ids[f] : -1;
      if (mat < -1 || mat >= int(obj_.materials.size())) mat = -1;
      auto [it, added] = group_of.try_emplace(mat, groups.size());
      if (added) groups.emplace_back().material = mat;
      Group& g = groups[it->second];
      uint32_t corner[256];
      for (size_t k = 0; k < n; ++k) corner[k] = addCorner(g, sm.indices[first + k], s, f);
      for (size_t k = 2; k < n; ++k)
        g.mesh.triangles.push_back({corner[0], corner[k - 1], corner[k]});
      total_triangles_ += n >= 3 ? n - 2 : 0;
      loader::checkLimits(path_, "the file", 0, total_triangles_, limits_);
    }
    return groups;
  }

 private:
  // The group's vertex of the corner's v/vn/vt triple, added when first seen.
  uint32_t addCorner(Group& g, const tinyobj::index_t& c, size_t s, size_t f) {
    if (c.vertex_index < 0 || c.vertex_index >= nv_ || c.normal_index >= nn_ ||
        c.texcoord_index >= nt_)
      throwInput(
          "{}: shape '{}' face {} refers to v/vt/vn {}/{}/{}, but the file has {} v, {} "
          "vt and {} vn (OBJ indices count from 1)",
          path_, obj_.shapes[s].name, f, c.vertex_index + 1, c.texcoord_index + 1,
          c.normal_index + 1, nv_, nt_, nn_);
    auto [ci, fresh] = g.index.try_emplace({c.vertex_index, c.normal_index, c.texcoord_index},
                                           uint32_t(g.mesh.positions.size()));
    if (!fresh) return ci->second;
    const tinyobj::attrib_t& a = obj_.attrib;
    const float* p = &a.vertices[3 * size_t(c.vertex_index)];
    g.mesh.positions.push_back({p[0], p[1], p[2]});
    if (!isFinite(g.mesh.positions.back()))
      throwInput("{}: vertex {} has a non-finite position", path_, c.vertex_index + 1);
    const float* nrm = c.normal_index >= 0 ? &a.normals[3 * size_t(c.normal_index)] : nullptr;
    g.mesh.normals.push_back(nrm ? vec3(nrm[0], nrm[1], nrm[2]) : vec3(0.0f));
    const float* uv = c.texcoord_index >= 0 ? &a.texcoords[2 * size_t(c.texcoord_index)] : nullptr;
    g.mesh.uvs.push_back(uv ? vec2(uv[0], uv[1]) : vec2(0.0f));
    g.all_normals = g.all_normals && nrm;
    g.any_uv = g.any_uv || uv;
    return ci->second;
  }

  const std::string& path_;
  const ObjFile& obj_;
  const LoadLimits& limits_;
  const int nv_, nn_, nt_;
  uint64_t total_triangles_ = 0;
};

// A shape's groups as the model's meshes: named, with normals (and tangents where mapped).
void addShapeMeshes(const std::string& path, const ObjFile& obj, size_t s,
                    std::vector<Group>& groups, LoadedModel& model) {
  for (Group& g : groups) {
    if (g.mesh.triangles.empty()) continue;  // lines or points only
    Mesh& m = g.mesh;
    const std::string& name = obj.shapes[s].name;
    std::string shape = name.empty() ? fmt::format("shape{}", s) : name;
    m.name = groups.size() > 1 && g.material >= 0
                 ? shape + "/" + obj.materials[size_t(g.material)].name
                 : shape;
    m.source = path;
    if (!g.any_uv) m.uvs.clear();
    if (!g.all_normals)
      m.computeNormals();
    else
      loader::repairNormals(m);
    if (g.material >= 0 && model.materials[size_t(g.material)].normal_map >= 0 && g.any_uv)
      m.computeTangents();
    model.meshes.push_back(std::move(m));
    model.mesh_material.push_back(g.material);
    model.mesh_transform.push_back(mat4(1.0f));
  }
}

}  // namespace

LoadedModel loadObj(const std::string& path, const LoadLimits& limits) {
  return readObj(path, loader::readWholeFile(path), limits);
}

LoadedModel readObj(const std::string& path, std::string text, const LoadLimits& limits) {
  preScan(path, text, limits);
  const ObjFile obj = parseObj(path, std::move(text));
  LoadedModel model;
  ObjMaterials converter(path, obj.mtl_of, model);
  for (size_t i = 0; i < obj.materials.size(); ++i)
    model.materials.push_back(converter.convert(i, obj.materials[i]));
  ShapeSplitter splitter(path, obj, limits);
  for (size_t s = 0; s < obj.shapes.size(); ++s) {
    std::vector<Group> groups = splitter.split(s);
    addShapeMeshes(path, obj, s, groups, model);
  }
  if (model.meshes.empty()) throwInput("{}: the OBJ file has no faces", path);
  return model;
}

}  // namespace mirage
