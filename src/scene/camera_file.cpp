#include "scene/camera_file.h"

#include "core/atomic_file.h"
#include "scene/scene_json_internal.h"

namespace mirage {

namespace {

using scene_json::Json;

Json vectorJson(const vec3& v) {
  return Json::array({v.x, v.y, v.z});
}

}  // namespace

CameraFile parseCameraFile(const std::string& file, const std::string& text) {
  Json doc = scene_json::parseDocument(file, text);
  CameraFile out;
  if (doc.contains("time")) {
    const Json time = doc["time"];
    out.time = scene_json::Field(file, time, "time").number(scene_json::Range::closed(0.0, 1e6));
    doc.erase("time");  // the rest is a camera of the scene format
  }
  out.camera = scene_json::parseCamera(scene_json::Field(file, doc, ""), 0);
  return out;
}

CameraFile loadCameraFile(const std::string& path) {
  return parseCameraFile(path, readFile(path));
}

std::string cameraFileText(const CameraDesc& c, std::optional<float> time) {
  // nlohmann writes a double in the fewest digits that read back to it; a float widened to
  // double reads back to the same float.
  Json j;
  j["name"] = c.name;
  if (time) j["time"] = *time;
  j["up"] = vectorJson(c.up);
  j["fov_y"] = c.fov_y_degrees;
  j["near"] = c.near_plane;
  j["far"] = c.far_plane;
  if (c.path.empty()) {
    j["position"] = vectorJson(c.position);
    j["target"] = vectorJson(c.target);
  } else {
    Json keys = Json::array();
    for (const CameraKey& k : c.path.keys)
      keys.push_back({{"time", k.time},
                      {"position", vectorJson(k.position)},
                      {"target", vectorJson(k.target)}});
    j["path"] = std::move(keys);
  }
  return j.dump(1) + "\n";
}

void saveCameraFile(const std::string& path, const CameraDesc& camera, std::optional<float> time) {
  writeFileAtomic(path, cameraFileText(camera, time));
}

}  // namespace mirage
