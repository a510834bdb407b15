// Cameras of the scene format (docs/scene-format.md, cameras[]): still ones and paths, each
// key and the spline between keys checked. Camera files (scene/camera_file.h) hold one of these.
#include "scene/scene_json_internal.h"

namespace mirage::scene_json {

namespace {

// Whether a camera at `position` looking at `target` has a direction not parallel to `up`.
bool canLook(const vec3& position, const vec3& target, const vec3& up) {
  return glm::length(target - position) > 1e-6f &&
         glm::length(glm::cross(glm::normalize(target - position), up)) > 1e-4f;
}

// "path": [{"time", "position", "target"}, ...], at least two keys with increasing times. The
// spline between keys is checked too, so that no frame of the walk looks straight up or at its
// own eye.
CameraPath parseCameraPath(const Field& f, const vec3& up) {
  std::vector<Field> items = f.items();
  if (items.size() < 2)
    f.fail("has {} key{}; a path needs at least 2 (the camera moves from one to the next)",
           items.size(), items.size() == 1 ? "" : "s");
  CameraPath path;
  for (const Field& k : items) {
    k.allowKeys({"time", "position", "target"}, "a camera path key");
    CameraKey key;
    key.time =
        keyTime(k, path.keys.empty() ? std::nullopt : std::optional<float>(path.keys.back().time));
    key.position = k.required("position").vector3(Range::closed(-1e6, 1e6));
    Field target = k.required("target");
    key.target = target.vector3(Range::closed(-1e6, 1e6));
    if (!(glm::length(key.target - key.position) > 1e-6f))
      target.fail("equals the position; the camera needs a direction to look in");
    if (!canLook(key.position, key.target, up))
      target.fail("- position is parallel to the camera's up; give a target off that line");
    path.keys.push_back(key);
  }
  constexpr int kSteps = 32;  // samples per segment
  for (size_t i = 0; i + 1 < path.keys.size(); ++i)
    for (int s = 1; s < kSteps; ++s) {
      float t = glm::mix(path.keys[i].time, path.keys[i + 1].time, float(s) / kSteps);
      CameraKey at = path.at(t);
      if (!canLook(at.position, at.target, up))
        f.fail(
            "at time {} (between keys {} and {}) has the target on the eye or straight along "
            "up; move the keys' targets further from their positions",
            t, i, i + 1);
    }
  return path;
}

}  // namespace

CameraDesc parseCamera(const Field& f, size_t index) {
  f.allowKeys({"name", "position", "target", "up", "fov_y", "near", "far", "path"}, "a camera");
  CameraDesc c;
  c.name = f.stringOr("name", fmt::format("camera-{}", index + 1));
  auto up = f.optional("up");
  if (up) c.up = up->vector3();
  if (auto path = f.optional("path")) {
    // The path's keys place the camera; a second, still placement would contradict them.
    for (const char* key : {"position", "target"})
      if (auto other = f.optional(key))
        other->fail("cannot be combined with path (the camera is where its path's keys put it)");
    if (up && !(glm::length(c.up) > 1e-6f)) up->fail("must be non-zero");
    c.path = parseCameraPath(*path, c.up);
    c.position = c.path.keys.front().position;
    c.target = c.path.keys.front().target;
  } else {
    c.position = f.required("position").vector3();
    Field target = f.required("target");
    c.target = target.vector3();
    if (!(glm::length(c.target - c.position) > 1e-6f))
      target.fail("equals the position; the camera needs a direction to look in");
    if (!canLook(c.position, c.target, c.up)) {
      if (up)
        up->fail("must be non-zero and not parallel to the view direction (target - position)");
      f.fail(
          "looks straight along the default up [0, 1, 0]; give an up not parallel to the view "
          "direction");
    }
  }
  c.fov_y_degrees = f.numberOr("fov_y", c.fov_y_degrees, Range{0.0, 180.0, true, true});
  c.near_plane = f.numberOr("near", c.near_plane, Range::above(0.0));
  if (auto far = f.optional("far")) {
    c.far_plane = far->number(Range::above(c.near_plane));
  } else if (c.far_plane <= c.near_plane) {
    f.required("near").fail("= {} must be less than far ({})", c.near_plane, c.far_plane);
  }
  return c;
}

}  // namespace mirage::scene_json
