#include "scene/gltf_scene_parts.h"

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "scene/loader_support.h"

namespace mirage::gltf {

namespace {

constexpr const char* kLightsExtension = "KHR_lights_punctual";

// The numbers a perspective camera needs, checked as floats too (what CameraDesc keeps): a yfov
// in (0, pi), znear > 0, zfar > znear when given (0: none), aspectRatio > 0 when given.
void checkPerspective(const std::string& what, const tinygltf::PerspectiveCamera& p) {
  auto fail = [&](const char* field, double value, const std::string& range) {
    throwInput("{}: perspective.{} = {} is outside the allowed range {}", what, field, value,
               range);
  };
  const float yfov_degrees = glm::degrees(float(p.yfov));
  if (!(p.yfov > 0.0 && yfov_degrees > 0.0f && yfov_degrees < 180.0f))
    fail("yfov", p.yfov, "(0, 3.14159) radians");
  const float znear = float(p.znear), zfar = float(p.zfar);
  if (!(znear > 0.0f && std::isfinite(znear))) fail("znear", p.znear, "> 0 (finite)");
  if (p.zfar != 0.0 && !(zfar > znear && std::isfinite(zfar)))
    fail("zfar", p.zfar, fmt::format("> znear = {} (finite)", p.znear));
  const float aspect = float(p.aspectRatio);
  if (p.aspectRatio != 0.0 && !(aspect > 0.0f && std::isfinite(aspect)))
    fail("aspectRatio", p.aspectRatio, "> 0 (finite)");
}

}  // namespace

void SceneParts::addNode(int index, const tinygltf::Node& node, const mat4& world) {
  if (node.camera >= 0) addCamera(index, node, world);
  if (node.extensions.count(kLightsExtension)) addLight(index, node, world);
}

void SceneParts::addCamera(int index, const tinygltf::Node& node, const mat4& world) {
  if (size_t(node.camera) >= gltf_.cameras.size())
    throwInput("{}: node {} refers to camera {}, but the file has {}", path_, index, node.camera,
               gltf_.cameras.size());
  const tinygltf::Camera& cam = gltf_.cameras[size_t(node.camera)];
  const std::string name = !cam.name.empty()    ? cam.name
                           : !node.name.empty() ? node.name
                                                : fmt::format("camera{}", node.camera);
  const std::string what = fmt::format("{}: camera '{}' (cameras[{}])", path_, name, node.camera);
  if (cam.type != "perspective") {
    spdlog::warn("{} is {}; skipped (mirage's cameras are perspective pinholes)", what,
                 cam.type.empty() ? "of no type" : cam.type);
    return;
  }
  const tinygltf::PerspectiveCamera& p = cam.perspective;
  checkPerspective(what, p);
  CameraDesc c = loader::placedCamera(what, world, vec3(0.0f), vec3(0, 0, -1), vec3(0, 1, 0));
  c.name = name;
  c.fov_y_degrees = glm::degrees(float(p.yfov));
  c.near_plane = float(p.znear);
  c.far_plane = float(p.zfar);  // 0 (infinite) until finish() knows the file's extent
  c.aspect = float(p.aspectRatio);
  if (p.zfar == 0.0) infinite_.push_back(cameras_.size());
  cameras_.push_back(std::move(c));
}

void SceneParts::addLight(int index, const tinygltf::Node& node, const mat4& world) {
  const tinygltf::Value& ref = node.extensions.at(kLightsExtension);
  if (!ref.IsObject() || !ref.Has("light") || !ref.Get("light").IsInt())
    throwInput("{}: node {} extensions.{} needs \"light\": the index of a light", path_, index,
               kLightsExtension);
  const int light = ref.Get("light").GetNumberAsInt();
  if (light < 0 || size_t(light) >= gltf_.lights.size())
    throwInput("{}: node {} extensions.{}.light = {} is outside 0..{}", path_, index,
               kLightsExtension, light, int(gltf_.lights.size()) - 1);
  const tinygltf::Light& l = gltf_.lights[size_t(light)];
  const std::string name = l.name.empty() ? fmt::format("lights[{}]", light)
                                          : fmt::format("'{}' (lights[{}])", l.name, light);
  const std::string what = fmt::format("{}: light {}", path_, name);
  if (l.type != "directional") {
    spdlog::warn("{} is a {} light; ignored (mirage has one directional light)", what, l.type);
    return;
  }
  if (light_) {
    spdlog::warn("{} is a second directional light; ignored (mirage has one: {})", what,
                 light_name_);
    return;
  }
  Light out;
  out.direction = loader::placedLightDirection(what, world, vec3(0, 0, -1));
  out.color = lightColor(what, l);
  light_ = out;
  light_name_ = name;
}

vec3 SceneParts::lightColor(const std::string& what, const tinygltf::Light& light) const {
  vec3 color(1.0f);
  if (!light.color.empty() && light.color.size() != 3)
    throwInput("{}: color has {} numbers; expected 3 (linear RGB)", what, light.color.size());
  for (size_t i = 0; i < light.color.size(); ++i) {
    color[int(i)] = float(light.color[i]);
    if (!(color[int(i)] >= 0.0f && std::isfinite(color[int(i)])))
      throwInput("{}: color[{}] = {} is outside the allowed range [0, 3.4e38]", what, i,
                 light.color[i]);
  }
  const float intensity = float(light.intensity);
  if (!(intensity >= 0.0f && std::isfinite(intensity) && isFinite(color * intensity)))
    throwInput("{}: intensity = {} is outside the allowed range [0, 3.4e38] (times the colour)",
               what, light.intensity);
  return color * intensity;
}

void SceneParts::finish(LoadedModel& out) {
  Bounds3 bounds;
  for (size_t i = 0; i < out.meshes.size(); ++i)
    bounds.extend(out.meshes[i].bounds().transformed(out.mesh_transform[i]));
  for (size_t i : infinite_) {
    CameraDesc& c = cameras_[i];
    float reach = 0.0f;
    for (int k = 0; k < 8 && !bounds.empty(); ++k) {
      const vec3 corner((k & 1) ? bounds.hi.x : bounds.lo.x, (k & 2) ? bounds.hi.y : bounds.lo.y,
                        (k & 4) ? bounds.hi.z : bounds.lo.z);
      reach = std::max(reach, glm::distance(c.position, corner));
    }
    c.far_plane = std::max({kInfiniteFar, 2.0f * reach, 2.0f * c.near_plane});
  }
  loader::uniqueCameraNames(path_, cameras_);
  out.cameras = std::move(cameras_);
  out.light = light_;
}

}  // namespace mirage::gltf
