// Loading meshes and models from files. The format is chosen by extension:
//   .ply, .ply.gz  PLY (ASCII, binary little/big endian; gzip-compressed)   — mirage's own reader
//   .obj           Wavefront OBJ with its .mtl materials                      — tinyobjloader
//   .gltf, .glb    glTF 2.0 (metallic 1 + roughness 0 is a reflector)         — tinygltf, or assimp
//                  when the file needs an extension tinygltf lacks (Draco)
//   anything else  assimp (FBX, 3DS, DAE, STL, ...)
// Every reader checks counts and sizes before allocating, and reports a malformed file with an
// InputError naming the file and, where it knows, the line/element and what was expected.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/memory_cap.h"
#include "scene/material.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace mirage {

// Caps on what one file may make mirage allocate (checked against header counts before any
// allocation; see docs/scene-format.md and docs/reliability.md).
struct LoadLimits {
  uint64_t max_vertices = 50'000'000;
  uint64_t max_triangles = 100'000'000;
  // The bytes one file may make us allocate: its mesh (loader::meshBytes) or the inflated bytes of
  // a gzip stream. The process's --max-memory when the limits are made (core/memory_cap.h).
  uint64_t max_bytes = maxMemory();
};

// A model file's content. Formats without materials (PLY, STL) give no materials and
// mesh_material = -1 for every mesh.
struct LoadedModel {
  std::vector<Mesh> meshes;          // with normals (computed if the file has none)
  std::vector<int> mesh_material;    // per mesh: index into `materials`, or -1
  std::vector<mat4> mesh_transform;  // per mesh: node transform of the file's scene graph
  // Per mesh: the name of the node that places it ("" when it has none); formats without nodes
  // (PLY, OBJ) give "" for every mesh.
  std::vector<std::string> mesh_node;
  std::vector<Material> materials;  // texture indices refer to `textures`
  std::vector<TextureImage> textures;
  // The file's perspective cameras in world space (glTF, and what assimp reads), uniquely named.
  std::vector<CameraDesc> cameras;
  // The file's first directional light, in world space; its ambient is Light's default.
  std::optional<Light> light;
};

// Loads any supported model file.
LoadedModel loadModel(const std::string& path, const LoadLimits& limits = {});
// Loads a file as one mesh: all its meshes, transformed by their node transforms, merged.
Mesh loadMesh(const std::string& path, const LoadLimits& limits = {});
// Whether `path` has an extension loadModel treats as a mesh/model file.
bool isModelFile(const std::string& path);

// The individual readers (used by loadModel; exposed for tests and fuzzing).
Mesh loadPly(const std::string& path, const LoadLimits& limits = {});
Mesh readPly(const std::string& name, const std::string& bytes, const LoadLimits& limits = {});
LoadedModel loadObj(const std::string& path, const LoadLimits& limits = {});
LoadedModel loadGltf(const std::string& path, const LoadLimits& limits = {});
// The same from a file's bytes in memory; `path` names it in messages and its folder is where
// the files it refers to (.mtl, glTF buffers and images) are looked for.
LoadedModel readObj(const std::string& path, std::string text, const LoadLimits& limits = {});
LoadedModel readGltf(const std::string& path, const std::string& bytes,
                     const LoadLimits& limits = {});
LoadedModel loadWithAssimp(const std::string& path, const LoadLimits& limits = {});

}  // namespace mirage
