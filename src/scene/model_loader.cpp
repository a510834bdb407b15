// Chooses the reader by extension and merges a model into one mesh for loadMesh.
#include "scene/model_loader.h"

#include <filesystem>

#include <assimp/Importer.hpp>

#include "core/error.h"
#include "scene/loader_support.h"

namespace mirage {

namespace {

bool ownReader(const std::string& ext) {
  return ext == ".ply" || ext == ".ply.gz" || ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

bool assimpReads(const std::string& ext) {
  // .json is a mirage scene file, whatever assimp thinks of it; other compressed files are
  // not model files either.
  if (ext.empty() || ext == ".json" || ext.ends_with(".gz")) return false;
  Assimp::Importer importer;
  return importer.IsExtensionSupported(ext);
}

// A mesh after its node transforms: a transform can overflow a position (a scale of 1e30) or
// collapse a normal (a scale of 0), which the file's own checks could not see.
Mesh placed(Mesh mesh) {
  mesh.validate();
  loader::repairNormals(mesh);
  return mesh;
}

}  // namespace

bool isModelFile(const std::string& path) {
  std::string ext = loader::lowerExtension(path);
  return ownReader(ext) || assimpReads(ext);
}

LoadedModel loadModel(const std::string& path, const LoadLimits& limits) {
  std::string ext = loader::lowerExtension(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throwInput("{}: no such file", path);
  if (std::filesystem::is_directory(path, ec))
    throwInput("{}: is a folder, not a model file", path);

  LoadedModel model;
  if (ext == ".ply" || ext == ".ply.gz")
    model = loader::singleMeshModel(loadPly(path, limits));
  else if (ext == ".obj")
    model = loadObj(path, limits);
  else if (ext == ".gltf" || ext == ".glb")
    model = loadGltf(path, limits);
  else if (assimpReads(ext))
    model = loadWithAssimp(path, limits);
  else
    throwInput(
        "{}: unsupported model file extension '{}' (supported: .ply, .ply.gz, .obj, .gltf, "
        ".glb, and what assimp reads: .fbx, .dae, .3ds, .stl, ...)",
        path, ext);

  // Readers of formats without nodes leave the node names out.
  if (model.mesh_node.empty()) model.mesh_node.resize(model.meshes.size());
  // The readers keep these in step; a mismatch is our bug, not the file's.
  if (model.mesh_material.size() != model.meshes.size() ||
      model.mesh_transform.size() != model.meshes.size() ||
      model.mesh_node.size() != model.meshes.size())
    throwRuntime(
        "{}: the reader returned {} meshes with {} materials, {} transforms and {} node names",
        path, model.meshes.size(), model.mesh_material.size(), model.mesh_transform.size(),
        model.mesh_node.size());
  if (model.meshes.empty()) throwInput("{}: the file holds no triangle meshes", path);
  for (const Mesh& m : model.meshes) m.validate();
  return model;
}

Mesh loadMesh(const std::string& path, const LoadLimits& limits) {
  LoadedModel model = loadModel(path, limits);
  if (model.meshes.size() == 1) {
    Mesh m = std::move(model.meshes[0]);
    if (model.mesh_transform[0] != mat4(1.0f)) m.transform(model.mesh_transform[0]);
    m.name = loader::fileStem(path);
    m.source = path;
    return placed(std::move(m));
  }
  Mesh out;
  out.name = loader::fileStem(path);
  out.source = path;
  // Attributes some meshes lack are dropped for all: a merged mesh has them per vertex or not.
  bool uvs = true, tangents = true;
  size_t vertices = 0, triangles = 0;
  for (const Mesh& m : model.meshes) {
    uvs = uvs && m.uvs.size() == m.positions.size();
    tangents = tangents && m.tangents.size() == m.positions.size();
    vertices += m.positions.size();
    triangles += m.triangles.size();
  }
  loader::checkLimits(path, "the merged mesh", vertices, triangles, limits);
  out.positions.reserve(vertices);
  out.normals.reserve(vertices);
  out.triangles.reserve(triangles);
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    Mesh& m = model.meshes[i];
    m.transform(model.mesh_transform[i]);
    uint32_t base = uint32_t(out.positions.size());
    out.positions.insert(out.positions.end(), m.positions.begin(), m.positions.end());
    out.normals.insert(out.normals.end(), m.normals.begin(), m.normals.end());
    if (uvs) out.uvs.insert(out.uvs.end(), m.uvs.begin(), m.uvs.end());
    if (tangents) out.tangents.insert(out.tangents.end(), m.tangents.begin(), m.tangents.end());
    for (const uvec3& t : m.triangles) out.triangles.push_back(t + uvec3(base));
  }
  return placed(std::move(out));
}

}  // namespace mirage
