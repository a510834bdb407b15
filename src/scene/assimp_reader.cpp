// Every format mirage has no reader of its own for (FBX, COLLADA, 3DS, STL, ...), and glTF files
// that need Draco, through assimp. Assimp reads whole files before we see them, so the limits are
// checked on its result, before mirage copies anything.
//
// Materials follow the other readers: metallic 1 with roughness 0 (glTF through assimp) is a
// reflector tinted by the base colour; otherwise the base/diffuse colour times the base/diffuse
// texture. Formats without materials (STL) get assimp's default material, reported as none (-1).
// Texture coordinates: assimp's origin is the image's bottom-left, as mirage's. Cameras and the
// light: assimp_scene_parts.h.
#include <algorithm>
#include <filesystem>

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "scene/assimp_scene_parts.h"
#include "scene/loader_support.h"
#include "scene/model_loader.h"

namespace mirage {

namespace {

mat4 toGlm(const aiMatrix4x4& a) {
  // aiMatrix4x4 is row-major (a1..a4 is the first row); glm is column-major.
  return glm::transpose(glm::make_mat4(&a.a1));
}

Image fromTexels(const aiTexture& t, Encoding encoding) {
  Image img(int(t.mWidth), int(t.mHeight));
  for (unsigned y = 0; y < t.mHeight; ++y)
    for (unsigned x = 0; x < t.mWidth; ++x) {
      const aiTexel& p = t.pcData[size_t(y) * t.mWidth + x];
      auto c = [&](uint8_t v) {
        return encoding == Encoding::kSrgb ? srgbToLinear(float(v) / 255.0f) : float(v) / 255.0f;
      };
      img(int(x), int(y)) = vec4(c(p.r), c(p.g), c(p.b), float(p.a) / 255.0f);
    }
  return img;
}

class AssimpConverter {
  static constexpr int kNotYet = -2;

 public:
  AssimpConverter(const std::string& path, const aiScene& scene, const LoadLimits& limits)
      : path_(path),
        scene_(scene),
        limits_(limits),
        gltf_(loader::lowerExtension(path) == ".gltf" || loader::lowerExtension(path) == ".glb"),
        textures_(out_.textures) {}

  LoadedModel run() {
    // Materials are converted when a mesh first uses one: assimp adds unused defaults (its
    // glTF importer appends one to every file), whose textures need not be decoded.
    std::vector<int> material_of(scene_.mNumMaterials, kNotYet);
    auto materialIndex = [&](unsigned i) {
      if (i >= scene_.mNumMaterials) return -1;
      if (material_of[i] == kNotYet) {
        const aiMaterial& m = *scene_.mMaterials[i];
        if (m.GetName() == aiString(AI_DEFAULT_MATERIAL_NAME)) {
          material_of[i] = -1;  // what assimp gives formats without materials (STL, PLY)
        } else {
          material_of[i] = int(out_.materials.size());
          out_.materials.push_back(material(m, i));
        }
      }
      return material_of[i];
    };
    assimp::SceneParts parts(path_, scene_, gltf_);
    std::vector<std::pair<const aiNode*, mat4>> stack;
    if (scene_.mRootNode) stack.push_back({scene_.mRootNode, mat4(1.0f)});
    while (!stack.empty()) {
      auto [node, parent] = stack.back();
      stack.pop_back();
      mat4 world = parent * toGlm(node->mTransformation);
      parts.addNode(*node, world);
      for (unsigned k = 0; k < node->mNumMeshes; ++k) {
        unsigned mi = node->mMeshes[k];
        if (mi >= scene_.mNumMeshes) continue;
        const aiMesh& am = *scene_.mMeshes[mi];
        if (!(am.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || am.mNumFaces == 0) continue;
        // Meshes placed by several nodes are copied once per node: count every copy.
        vertices_ += am.mNumVertices;
        triangles_ += am.mNumFaces;
        loader::checkLimits(path_, "the file", vertices_, triangles_, limits_);
        out_.meshes.push_back(mesh(am, mi));
        int mat = materialIndex(am.mMaterialIndex);
        out_.mesh_material.push_back(mat);
        out_.mesh_transform.push_back(world);
        out_.mesh_node.push_back(node->mName.C_Str());
        Mesh& m = out_.meshes.back();
        if (mat >= 0 && out_.materials[size_t(mat)].normal_map >= 0 && !m.uvs.empty())
          m.computeTangents();
      }
      for (unsigned c = node->mNumChildren; c-- > 0;) stack.push_back({node->mChildren[c], world});
    }
    if (out_.meshes.empty()) throwInput("{}: the file has no triangle meshes", path_);
    parts.finish(out_);
    return std::move(out_);
  }

 private:
  Mesh mesh(const aiMesh& am, unsigned index) {
    Mesh m;
    m.name = am.mName.length ? std::string(am.mName.C_Str()) : fmt::format("mesh{}", index);
    m.source = path_;
    m.positions.resize(am.mNumVertices);
    for (unsigned i = 0; i < am.mNumVertices; ++i) {
      const aiVector3D& p = am.mVertices[i];
      m.positions[i] = vec3(p.x, p.y, p.z);
      if (!isFinite(m.positions[i]))
        throwInput("{}: mesh {} vertex {} has a non-finite position", path_, m.name, i);
    }
    if (am.HasNormals()) {
      m.normals.resize(am.mNumVertices);
      for (unsigned i = 0; i < am.mNumVertices; ++i)
        m.normals[i] = vec3(am.mNormals[i].x, am.mNormals[i].y, am.mNormals[i].z);
    }
    if (am.HasTextureCoords(0)) {
      m.uvs.resize(am.mNumVertices);
      for (unsigned i = 0; i < am.mNumVertices; ++i)
        m.uvs[i] = vec2(am.mTextureCoords[0][i].x, am.mTextureCoords[0][i].y);
    }
    m.triangles.reserve(am.mNumFaces);
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
      const aiFace& face = am.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by SortByPType
      uvec3 t(face.mIndices[0], face.mIndices[1], face.mIndices[2]);
      if (t.x >= am.mNumVertices || t.y >= am.mNumVertices || t.z >= am.mNumVertices)
        throwInput("{}: mesh {} face {} refers to a vertex past its {}", path_, m.name, f,
                   am.mNumVertices);
      m.triangles.push_back(t);
    }
    loader::repairNormals(m);
    return m;
  }

  Material material(const aiMaterial& a, unsigned index) {
    std::string name = a.GetName().length ? a.GetName().C_Str() : fmt::format("material{}", index);
    aiColor4D c(1, 1, 1, 1);
    if (a.Get(AI_MATKEY_BASE_COLOR, c) != AI_SUCCESS) {
      aiColor3D d(0.8f, 0.8f, 0.8f);
      a.Get(AI_MATKEY_COLOR_DIFFUSE, d);
      c = aiColor4D(d.r, d.g, d.b, 1.0f);
    }
    vec3 color(c.r, c.g, c.b);
    float metallic = 0.0f, roughness = 1.0f;
    bool pbr = a.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS &&
               a.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS;
    Material m;
    if (pbr && metallic == 1.0f && roughness == 0.0f) {
      m = Material::mirror(name, vec3(0.05f), color);
    } else {
      m = Material::diffuse(name, color);
      m.albedo_texture = texture(a, aiTextureType_BASE_COLOR, Encoding::kSrgb, name);
      if (m.albedo_texture < 0)
        m.albedo_texture = texture(a, aiTextureType_DIFFUSE, Encoding::kSrgb, name);
    }
    m.normal_map = texture(a, aiTextureType_NORMALS, Encoding::kLinear, name);
    return m;
  }

  int texture(const aiMaterial& a, aiTextureType type, Encoding encoding, const std::string& mat) {
    aiString ref;
    if (a.GetTextureCount(type) == 0 || a.GetTexture(type, 0, &ref) != AI_SUCCESS) return -1;
    std::string name = ref.C_Str();
    if (const aiTexture* t = scene_.GetEmbeddedTexture(ref.C_Str())) {
      std::string key = fmt::format("{}#{}", path_, name);
      return textures_.get(key, encoding, [&] {
        if (t->mHeight == 0)  // compressed (PNG, JPEG, ...): mWidth is the size in bytes
          return readImageFromMemory(key + "." + t->achFormatHint, t->pcData, t->mWidth, encoding);
        return fromTexels(*t, encoding);
      });
    }
    const std::string file = loader::textureFile(loader::folderOf(path_), name);
    if (file.empty()) return textures_.missing(fmt::format("{}: material {}", path_, mat), name);
    return textures_.get(file, encoding, [&] { return readImage(file, encoding); });
  }

  const std::string& path_;
  const aiScene& scene_;
  const LoadLimits& limits_;
  bool gltf_;  // assimp's glTF importer has conventions of its own (assimp_scene_parts.h)
  uint64_t vertices_ = 0, triangles_ = 0;
  LoadedModel out_;
  loader::TextureList textures_;
};

}  // namespace

LoadedModel loadWithAssimp(const std::string& path, const LoadLimits& limits) {
  Assimp::Importer importer;
  // Points and lines cannot be rendered: drop them instead of making meshes of them.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // GenSmoothNormals only fills meshes that have no normals.
  unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                   aiProcess_GenSmoothNormals | aiProcess_SortByPType |
                   aiProcess_ValidateDataStructure | aiProcess_FindInvalidData;
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode)
    throwInput("{}: {}", path,
               scene ? "the file describes no complete scene" : importer.GetErrorString());
  return AssimpConverter(path, *scene, limits).run();
}

}  // namespace mirage
