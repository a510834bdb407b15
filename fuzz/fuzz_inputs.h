// The parsers the fuzz targets drive, one function per input format, shared by the libFuzzer
// targets (fuzz_<name>.cpp) and by the unit test that replays the checked-in corpus — seeds and
// the regression inputs of every crash found — in every ordinary test run
// (tests/fuzz/corpus_test.cpp). Each may only ever throw InputError.
#pragma once

#include <string>

#include "core/image.h"
#include "scene/camera_file.h"
#include "scene/model_loader.h"
#include "scene/scene_json.h"
#include "viewer/input.h"

namespace mirage::fuzz {

// Small caps, so that the checks before allocation are what a hostile header reaches (16 MiB a
// mesh; images get the targets' --max-memory, fuzz_common.h).
inline const LoadLimits kLimits{100000, 200000, 16u << 20};

inline void sceneJson(const std::string& bytes) {
  parseSceneJson("fuzz.json", bytes, "").validate();
}
inline void ply(const std::string& bytes) {
  readPly("fuzz.ply", bytes, kLimits);
}
// Files an OBJ or glTF names (.mtl, buffers, images) are looked for in a folder that does not
// exist; data: URIs are read.
inline void obj(const std::string& bytes) {
  readObj("/nonexistent/fuzz.obj", bytes, kLimits);
}
inline void gltf(const std::string& bytes) {
  readGltf("/nonexistent/fuzz.gltf", bytes, kLimits);
}
inline void exr(const std::string& bytes) {
  readImageFromMemory("fuzz.exr", bytes.data(), bytes.size(), Encoding::kLinear);
}
// Radiance HDR and the other formats stb reads (PNG, JPEG, TGA, BMP).
inline void hdr(const std::string& bytes) {
  readImageFromMemory("fuzz.hdr", bytes.data(), bytes.size(), Encoding::kLinear);
}
inline void cameraPath(const std::string& bytes) {
  parseCameraFile("fuzz.json", bytes);
}
inline void eventScript(const std::string& bytes) {
  parseEventScript("fuzz.json", bytes);
}

struct Target {
  const char* name;  // the corpus folder, tests/fuzz/corpus/<name>
  void (*parse)(const std::string&);
};
inline constexpr Target kTargets[] = {
    {"scene_json", sceneJson},
    {"ply", ply},
    {"obj", obj},
    {"gltf", gltf},
    {"exr", exr},
    {"hdr", hdr},
    {"camera_path", cameraPath},
    {"event_script", eventScript},
};

}  // namespace mirage::fuzz
