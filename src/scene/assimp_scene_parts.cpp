#include "scene/assimp_scene_parts.h"

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "scene/loader_support.h"

namespace mirage::assimp {

namespace {

vec3 toGlm(const aiVector3D& v) {
  return {v.x, v.y, v.z};
}

const char* lightType(aiLightSourceType type) {
  switch (type) {
    case aiLightSource_POINT:
      return "point";
    case aiLightSource_SPOT:
      return "spot";
    case aiLightSource_AMBIENT:
      return "ambient";
    case aiLightSource_AREA:
      return "area";
    default:
      return "undefined";
  }
}

}  // namespace

SceneParts::SceneParts(const std::string& path, const aiScene& scene, bool gltf)
    : path_(path),
      scene_(scene),
      gltf_(gltf),
      camera_placed_(scene.mNumCameras, 0),
      light_placed_(scene.mNumLights, 0) {
  for (unsigned i = 0; i < scene.mNumCameras; ++i)
    cameras_by_node_.emplace(scene.mCameras[i]->mName.C_Str(), i);
  for (unsigned i = 0; i < scene.mNumLights; ++i)
    lights_by_node_.emplace(scene.mLights[i]->mName.C_Str(), i);
}

void SceneParts::addNode(const aiNode& node, const mat4& world) {
  const std::string name = node.mName.C_Str();
  // Node names should be unique; when they are not, the first node places the camera.
  for (auto [it, end] = cameras_by_node_.equal_range(name); it != end; ++it)
    if (!camera_placed_[it->second]++) addCamera(it->second, world);
  for (auto [it, end] = lights_by_node_.equal_range(name); it != end; ++it)
    if (!light_placed_[it->second]++) addLight(it->second, world);
}

float SceneParts::verticalFov(const std::string& what, const aiCamera& a) const {
  const float hfov = a.mHorizontalFOV, aspect = a.mAspect;
  if (!(hfov > 0.0f && hfov < kPi))
    throwInput(
        "{}: the horizontal field of view (mHorizontalFOV) = {} is outside the allowed "
        "range (0, 3.14159) radians",
        what, hfov);
  if (!(aspect >= 0.0f && std::isfinite(aspect)))
    throwInput("{}: the aspect ratio (mAspect) = {} is outside the allowed range >= 0 (0: none)",
               what, aspect);
  if (gltf_) return glm::degrees(aspect > 0.0f ? hfov / aspect : hfov);
  if (aspect > 0.0f) return glm::degrees(2.0f * std::atan(std::tan(0.5f * hfov) / aspect));
  spdlog::warn(
      "{}: the file gives no aspect ratio; its horizontal field of view ({} degrees) is "
      "taken as the vertical one",
      what, glm::degrees(hfov));
  return glm::degrees(hfov);
}

void SceneParts::addCamera(unsigned index, const mat4& world) {
  const aiCamera& a = *scene_.mCameras[index];
  const std::string name = a.mName.length ? a.mName.C_Str() : fmt::format("camera{}", index);
  const std::string what = fmt::format("{}: camera '{}' (cameras[{}])", path_, name, index);
  if (a.mOrthographicWidth > 0.0f) {
    spdlog::warn("{} is orthographic; skipped (mirage's cameras are perspective pinholes)", what);
    return;
  }
  const float fov = verticalFov(what, a);
  if (!(fov > 0.0f && fov < 180.0f))
    throwInput("{}: its vertical field of view = {} degrees is outside the allowed range (0, 180)",
               what, fov);
  if (!(a.mClipPlaneNear > 0.0f && std::isfinite(a.mClipPlaneNear)))
    throwInput("{}: the near plane (mClipPlaneNear) = {} is outside the allowed range > 0", what,
               a.mClipPlaneNear);
  if (!(a.mClipPlaneFar > a.mClipPlaneNear && std::isfinite(a.mClipPlaneFar)))
    throwInput("{}: the far plane (mClipPlaneFar) = {} is outside the allowed range > near = {}",
               what, a.mClipPlaneFar, a.mClipPlaneNear);
  const vec3 eye = gltf_ ? vec3(0.0f) : toGlm(a.mPosition);
  CameraDesc c = loader::placedCamera(what, world, eye, toGlm(a.mLookAt), toGlm(a.mUp));
  c.name = name;
  c.fov_y_degrees = fov;
  c.near_plane = a.mClipPlaneNear;
  c.far_plane = a.mClipPlaneFar;
  c.aspect = a.mAspect;
  cameras_.push_back(std::move(c));
}

void SceneParts::addLight(unsigned index, const mat4& world) {
  const aiLight& a = *scene_.mLights[index];
  const std::string name = a.mName.length ? fmt::format("'{}' (lights[{}])", a.mName.C_Str(), index)
                                          : fmt::format("lights[{}]", index);
  const std::string what = fmt::format("{}: light {}", path_, name);
  if (a.mType != aiLightSource_DIRECTIONAL) {
    spdlog::warn("{} is a {} light; ignored (mirage has one directional light)", what,
                 lightType(a.mType));
    return;
  }
  if (light_) {
    spdlog::warn("{} is a second directional light; ignored (mirage has one: {})", what,
                 light_name_);
    return;
  }
  const vec3 color(a.mColorDiffuse.r, a.mColorDiffuse.g, a.mColorDiffuse.b);
  if (!(glm::all(glm::greaterThanEqual(color, vec3(0.0f))) && isFinite(color)))
    throwInput("{}: its colour ({}, {}, {}) is outside the allowed range [0, 3.4e38] each", what,
               color.x, color.y, color.z);
  Light out;
  out.direction = loader::placedLightDirection(what, world, toGlm(a.mDirection));
  out.color = color;
  light_ = out;
  light_name_ = name;
}

void SceneParts::finish(LoadedModel& out) {
  for (unsigned i = 0; i < scene_.mNumCameras; ++i)
    if (!camera_placed_[i])
      spdlog::warn("{}: camera '{}' has no node of its name; skipped", path_,
                   scene_.mCameras[i]->mName.C_Str());
  for (unsigned i = 0; i < scene_.mNumLights; ++i)
    if (!light_placed_[i])
      spdlog::warn("{}: light '{}' has no node of its name; ignored", path_,
                   scene_.mLights[i]->mName.C_Str());
  loader::uniqueCameraNames(path_, cameras_);
  out.cameras = std::move(cameras_);
  out.light = light_;
}

}  // namespace mirage::assimp
