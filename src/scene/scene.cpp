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

std::vector<int> Scene::diffuseInstances() const {
  std::vector<int> out;
  for (size_t i = 0; i < instances.size(); ++i)
    if (!isReflector(int(i))) out.push_back(int(i));
  return out;
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Instance& inst : instances) n += meshes[size_t(inst.mesh)].triangleCount();
  return n;
}

Bounds3 Scene::localBounds(int instance) const {
  const Instance& inst = instances[size_t(instance)];
  Bounds3 local = meshes[size_t(inst.mesh)].bounds();
  const float grow = inst.deformation.maxDisplacement();
  if (grow > 0.0f && !local.empty()) {
    local.lo -= vec3(grow);
    local.hi += vec3(grow);
  }
  return local;
}

Bounds3 Scene::instanceBounds(int instance, float time) const {
  return localBounds(instance).transformed(instances[size_t(instance)].matrixAt(time));
}

void Scene::meshAt(int instance, float time, Mesh& out) const {
  const Instance& inst = instances[size_t(instance)];
  const Mesh& rest = meshes[size_t(inst.mesh)];
  if (inst.deforms())
    deformMesh(rest, inst.deformation, time, out);
  else
    out = rest;
}

Light Light::at(float time) const {
  Light l = *this;
  l.keys.clear();
  if (keys.empty()) return l;
  const KeySpan span = keySpan(keys, time, loop);
  const LightKey &a = keys[span.a], &b = keys[span.b];
  l.direction = a.direction;
  l.color = a.color;
  if (span.a == span.b) return l;
  const float u = span.u;
  // Slerp of unit vectors: a constant angular speed from one key's direction to the next.
  const float cos_angle = std::clamp(glm::dot(a.direction, b.direction), -1.0f, 1.0f);
  const float angle = std::acos(cos_angle);
  if (angle < 1e-4f) {
    l.direction = glm::normalize(glm::mix(a.direction, b.direction, u));
  } else {
    const float s = std::sin(angle);
    l.direction = glm::normalize(std::sin((1.0f - u) * angle) / s * a.direction +
                                 std::sin(u * angle) / s * b.direction);
  }
  l.color = glm::mix(a.color, b.color, u);
  return l;
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
  float d = light.duration();
  for (const Instance& inst : instances)
    d = std::max({d, inst.animation.duration(), inst.deformation.period()});
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
    if (!inst.deforms()) continue;
    const Deformation& d = inst.deformation;
    if (!materials[size_t(inst.material)].isReflector())
      throwInput("{}: deform: only reflectors deform (material '{}' is diffuse)",
                 where("instances", i, inst.name), materials[size_t(inst.material)].name);
    if (!(d.wavelength > 0.0f) || !std::isfinite(d.wavelength) || !std::isfinite(d.amplitude) ||
        !std::isfinite(d.speed) || !(d.decay >= 0.0f) || !isFinite(d.center))
      throwInput("{}: deform: needs wavelength > 0, decay >= 0 and finite values",
                 where("instances", i, inst.name));
    for (size_t j = 0; j < instances.size(); ++j)
      if (j != i && instances[j].mesh == inst.mesh)
        throwInput(
            "{}: deform: its mesh is shared with instances[{}]; a deforming instance needs "
            "a mesh of its own",
            where("instances", i, inst.name), j);
  }
  for (size_t k = 0; k < light.keys.size(); ++k) {
    const LightKey& key = light.keys[k];
    if (k > 0 && !(key.time > light.keys[k - 1].time))
      throwInput("{}: light.keys[{}].time = {} must be greater than the previous key's time ({})",
                 source.empty() ? name : source, k, key.time, light.keys[k - 1].time);
    if (!(std::abs(glm::length(key.direction) - 1.0f) < 1e-3f))
      throwInput("{}: light.keys[{}].direction must be a unit vector",
                 source.empty() ? name : source, k);
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
  // A deforming surface is not flat, whatever its rest shape.
  if (scene.instances[size_t(instance)].deforms()) return false;
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
