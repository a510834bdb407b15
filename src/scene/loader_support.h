// What the model readers share: file-name helpers, the LoadLimits checks with one message
// format, and a texture list that decodes each (file, encoding) pair once.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "scene/model_loader.h"

namespace mirage::loader {

// The lower-case extension, with ".gz" kept together with the one before it: "a/B.PLY.gz" ->
// ".ply.gz", "x.obj" -> ".obj", "noext" -> "".
std::string lowerExtension(const std::string& path);
// The file name without folders and extensions: "a/dragon.ply.gz" -> "dragon".
std::string fileStem(const std::string& path);
// The folder of `path` ("" for a bare file name), with a trailing '/' when not empty.
std::string folderOf(const std::string& path);

// Reads a whole file with one allocation and one read (core's readFile grows its string through
// an istreambuf_iterator: several times slower on the 34 MB dragon). InputError names the file.
std::string readWholeFile(const std::string& path);

// Throws InputError unless `vertices` and `triangles` are within the limits. `what` says what was
// counted ("element vertex", "mesh 'body'") for the message.
// And unless the mesh they make fits in limits.max_bytes (meshBytes).
void checkLimits(const std::string& file, const std::string& what, uint64_t vertices,
                 uint64_t triangles, const LoadLimits& limits);
// What a mesh of this many vertices and triangles costs while it is read: positions, normals,
// texture coordinates and tangents (48 bytes a vertex) and indices (12 bytes a triangle), plus as
// much again for the readers' staging of the file's own arrays. Saturates instead of wrapping.
uint64_t meshBytes(uint64_t vertices, uint64_t triangles);

// The file of a texture that a model in `folder` names: the name as given (absolute, or relative
// to the folder; Windows' backslashes read as slashes), else its file name alone in the folder, as
// Blender and three.js look for a file written on another machine ("D:/projects/..."). Empty
// where neither exists.
std::string textureFile(const std::string& folder, std::string name);

// The model's textures, each decoded once per (key, encoding).
class TextureList {
 public:
  explicit TextureList(std::vector<TextureImage>& textures) : textures_(textures) {}
  // The index of the texture known as `key` with this encoding; `decode` is called only the first
  // time and returns the image.
  int get(const std::string& key, Encoding encoding, const std::function<Image()>& decode);
  // A texture whose file does not exist, as Blender, assimp's viewer and three.js take it: one
  // warning per file (`where`: the model or material file and the material), and the material
  // without that texture (-1).
  int missing(const std::string& where, const std::string& file);

 private:
  std::vector<TextureImage>& textures_;
  std::map<std::pair<std::string, Encoding>, int> index_;
  std::set<std::string> missing_;
};

// A model holding one mesh without a material, placed by the identity transform.
LoadedModel singleMeshModel(Mesh mesh);

// A camera whose eye, view direction and up are given in its node's space, placed by the node's
// world matrix. The directions are normalised after the transform (a node may scale); `what`
// names the camera ("scene.gltf: camera 'cam_a'") in the InputError when the transform collapses
// them, makes them parallel or leaves the eye not finite.
CameraDesc placedCamera(const std::string& what, const mat4& world, vec3 eye, vec3 forward,
                        vec3 up);
// The unit direction towards a directional light that shines along `shine` in its node's space,
// placed by the node's world matrix (InputError naming `what` when the transform collapses it).
vec3 placedLightDirection(const std::string& what, const mat4& world, vec3 shine);
// `name`, or the first of name-2, name-3, ... not in `taken`; the result is added to `taken`.
std::string uniqueName(const std::string& name, std::set<std::string>& taken);
// Renames repeated camera names (and those in `taken`) by uniqueName, warning about each with
// `file`'s name.
void uniqueCameraNames(const std::string& file, std::vector<CameraDesc>& cameras,
                       std::set<std::string> taken = {});

// Normalises the given normals; when any is zero or not finite, recomputes them all from the
// triangles (a file's broken normals would otherwise shade black). Returns whether it recomputed.
bool repairNormals(Mesh& mesh);

}  // namespace mirage::loader
