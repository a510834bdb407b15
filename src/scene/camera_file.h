// Camera files: one camera of the scene format (docs/scene-format.md, `cameras[]`) in a file of
// its own — a still camera (position, target) or a path of keys. The viewer records paths and
// writes the camera of every screenshot into one; `mirage render|bench|view --camera-path`
// read them.
#pragma once

#include <optional>
#include <string>

#include "core/camera.h"

namespace mirage {

struct CameraFile {
  CameraDesc camera;
  // "time": the scene time a screenshot was taken at; commands take it as their --time when none
  // is given, so that the file reproduces the shot.
  std::optional<float> time;
};

// Reads and checks a camera file; throws InputError naming the file and the field.
CameraFile loadCameraFile(const std::string& path);
// The camera parsed from `text` (`file` names it in messages).
CameraFile parseCameraFile(const std::string& file, const std::string& text);
// The file's text for `camera`: every float written so that it reads back to the same float.
std::string cameraFileText(const CameraDesc& camera, std::optional<float> time = std::nullopt);
// Writes `camera` to `path` atomically.
void saveCameraFile(const std::string& path, const CameraDesc& camera,
                    std::optional<float> time = std::nullopt);

}  // namespace mirage
