#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include <spdlog/spdlog.h>

#include "core/error.h"

namespace mirage {

std::vector<int> Scene::reflectorInstances() const {
  std::vector<int> out;
  for (size_t i = 0; i < instances.size(); ++i)
    if (isReflector(int(i))) out.push_back(int(i));
  return out;
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Instance& inst : instances) n += meshes[size_t(inst.mesh)].triangleCount();
  return n;
}

Bounds3 Scene::instanceBounds(int instance, float time) const {
  const Instance& inst = instances[size_t(instance)];
  return meshes[size_t(inst.mesh)].bounds().transformed(inst.matrixAt(time));
}

Bounds3 Scene::bounds(float time) const {
  Bounds3 b;
  for (size_t i = 0; i < instances.size(); ++i) b.extend(instanceBounds(int(i), time));
  return b;
}

const CameraDesc& Scene::camera(const std::string& wanted) const {
  if (cameras.empty()) throwInput("scene '{}' has no camera", name);
  if (wanted.empty()) return cameras.front();
  std::string names;
  for (const CameraDesc& c : cameras) {
    if (c.name == wanted) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throwInput("scene '{}' has no camera '{}' (it has: {})", name, wanted, names);
}

float Scene::duration() const {
  float d = 0.0f;
  for (const Instance& inst : instances) d = std::max(d, inst.animation.duration());
  return d;
}

void Scene::validate() const {
  auto where = [&](const char* kind, size_t i, const std::string& n) {
    return fmt::format("{}: {}[{}]{}", source.empty() ? name : source, kind, i,
                       n.empty() ? "" : " ('" + n + "')");
  };
  if (instances.empty())
    throwInput("{}: the scene has no instances", source.empty() ? name : source);
  for (size_t i = 0; i < meshes.size(); ++i) meshes[i].validate();
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material& m = materials[i];
    auto in01 = [&](float v, const char* field) {
      if (!(v >= 0.0f && v <= 1.0f))
        throwInput("{}: {} = {} is outside the allowed range [0, 1]", where("materials", i, m.name),
                   field, v);
    };
    in01(m.reflectivity, "reflectivity");
    in01(m.fresnel_f0, "fresnel_f0");
    if (!(m.attenuation_range >= 0.0f))
      throwInput("{}: attenuation_range = {} must be >= 0", where("materials", i, m.name),
                 m.attenuation_range);
    for (int tex : {m.albedo_texture, m.normal_map})
      if (tex < -1 || tex >= int(textures.size()))
        throwInput("{}: texture index {} is outside 0..{}", where("materials", i, m.name), tex,
                   int(textures.size()) - 1);
  }
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& inst = instances[i];
    if (inst.mesh < 0 || inst.mesh >= int(meshes.size()))
      throwInput("{}: mesh index {} is outside 0..{}", where("instances", i, inst.name), inst.mesh,
                 int(meshes.size()) - 1);
    if (inst.material < 0 || inst.material >= int(materials.size()))
      throwInput("{}: material index {} is outside 0..{}", where("instances", i, inst.name),
                 inst.material, int(materials.size()) - 1);
  }
  for (size_t i = 0; i < cameras.size(); ++i) {
    const CameraDesc& c = cameras[i];
    if (!(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
      throwInput("{}: fov_y = {} is outside the allowed range (0, 180)",
                 where("cameras", i, c.name), c.fov_y_degrees);
    if (!(c.near_plane > 0.0f && c.far_plane > c.near_plane))
      throwInput("{}: near = {}, far = {}: need 0 < near < far", where("cameras", i, c.name),
                 c.near_plane, c.far_plane);
    // Scene files check their paths key by key (scene_json); this catches scenes built in code.
    if (!c.path.empty() && c.path.keys.size() < 2)
      throwInput("{}: the path has 1 key; a path needs at least 2", where("cameras", i, c.name));
    for (size_t k = 1; k < c.path.keys.size(); ++k)
      if (!(c.path.keys[k].time > c.path.keys[k - 1].time))
        throwInput("{}: path[{}].time = {} must be greater than the previous key's time ({})",
                   where("cameras", i, c.name), k, c.path.keys[k].time, c.path.keys[k - 1].time);
  }
}

void Scene::ensureCamera() {
  if (!cameras.empty()) return;
  Bounds3 b = bounds();
  CameraDesc c = frameBounds(b.center(), std::max(b.radius(), 1e-3f), vec3(0.3f, 0.45f, 1.0f));
  c.name = "auto";
  cameras.push_back(c);
}

bool isPlanarInstance(const Scene& scene, int instance, const mat4& model, vec3* normal) {
  const Bounds3 b = scene.meshes[size_t(scene.instances[size_t(instance)].mesh)].bounds();
  if (b.empty()) return false;
  const vec3 e = b.extent();
  const int thin = e.x <= e.y && e.x <= e.z ? 0 : (e.y <= e.z ? 1 : 2);
  if (!(e[thin] <= 1e-4f * std::max({e.x, e.y, e.z}))) return false;
  if (normal) {
    vec3 axis(0.0f);
    axis[thin] = 1.0f;
    *normal = glm::normalize(normalMatrix(model) * axis);
  }
  return true;
}

std::vector<int> planarReflectors(const Scene& scene, int* not_planar, const char* method) {
  std::vector<int> planar;
  int others = 0;
  for (int i : scene.reflectorInstances()) {
    const Instance& instance = scene.instances[size_t(i)];
    if (isPlanarInstance(scene, i, instance.matrixAt(0.0f))) {
      planar.push_back(i);
      continue;
    }
    ++others;
    const Material& material = scene.materials[size_t(instance.material)];
    if (material.planar)
      spdlog::warn(
          "{}: reflector '{}' is not planar, though its material '{}' declares \"planar\": true; "
          "it is shown as the method shows curved reflectors",
          method, instance.name, material.name);
  }
  if (not_planar) *not_planar = others;
  return planar;
}

bool planarInstancePlane(const Scene& scene, int instance, const mat4& model, const vec3& eye,
                         vec3& point, vec3& normal) {
  if (!isPlanarInstance(scene, instance, model, &normal)) return false;
  const Mesh& mesh = scene.meshes[size_t(scene.instances[size_t(instance)].mesh)];
  point = vec3(model * vec4(mesh.bounds().center(), 1.0f));
  const float side = glm::dot(normal, eye - point);
  if (std::abs(side) <= 1e-6f * std::max(glm::length(eye - point), 1e-6f)) return false;
  if (side < 0.0f) normal = -normal;
  return true;
}

vec3 sampleTexture(const Image& img, vec2 uv) {
  float x = uv.x * float(img.width()) - 0.5f, y = (1.0f - uv.y) * float(img.height()) - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int xi, int yi) {
    xi = ((xi % img.width()) + img.width()) % img.width();
    yi = ((yi % img.height()) + img.height()) % img.height();
    return vec3(img(xi, yi));
  };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx),
                  glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

}  // namespace mirage
