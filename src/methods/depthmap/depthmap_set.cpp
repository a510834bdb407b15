#include "methods/depthmap/depthmap_set.h"

#include <algorithm>
#include <cmath>

#include "methods/impostor/billboard_set.h"

namespace mirage {

namespace {

// The six viewing directions of an object's maps, in world space: towards the reflectors, away
// from them, then around that axis.
std::vector<vec3> mapDirections(const vec3& towards_reflectors) {
  const vec3 a = towards_reflectors;
  const vec3 helper = std::abs(a.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0);
  const vec3 b = glm::normalize(glm::cross(helper, a));
  const vec3 c = glm::cross(a, b);
  return {a, -a, b, -b, c, -c};
}

// The bounding sphere (centre, radius) in the space of instance i under `model` of what its
// maps frame: its own mesh, or a group's world bounds (still members, so fixed in i's space).
void frameOf(const Scene& scene, int i, const mat4& model, const std::vector<int>& members,
             vec3& centre, float& radius) {
  const Bounds3 local = scene.localBounds(i);
  if (members.empty()) {
    centre = local.center();
    radius = std::max(local.radius(), 1e-6f);
    return;
  }
  Bounds3 world = scene.instanceBounds(i, 0.0f);
  for (int m : members) world.extend(scene.instanceBounds(m, 0.0f));
  const mat3 linear(model);
  // depthMapView scales the radius by the largest axis scale: the smallest keeps it enclosing.
  const float smallest = std::max(
      {std::min({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])}), 1e-12f});
  centre = transformPoint(glm::inverse(model), world.center());
  radius = std::max(world.radius() / smallest, 1e-6f);
}

// Appends `count` maps of instance i (with a group's other `members`), the first looking from
// the point `viewer` (world, time 0).
void placeMaps(const Scene& scene, int i, const std::vector<int>& members, const mat4& model,
               const vec3& viewer, int count, bool reflector, std::vector<DepthMapSpec>& specs) {
  if (scene.localBounds(i).empty()) return;
  vec3 centre;
  float radius = 0.0f;
  frameOf(scene, i, model, members, centre, radius);
  const vec3 world_centre = transformPoint(model, centre);
  vec3 towards = viewer - world_centre;
  towards = glm::length(towards) > 1e-6f ? glm::normalize(towards) : vec3(0, 0, 1);
  const mat3 to_local = glm::inverse(mat3(model));
  const std::vector<vec3> dirs = mapDirections(towards);
  for (int k = 0; k < count; ++k) {
    const vec3 from = dirs[size_t(k)];
    const vec3 up_world = std::abs(from.y) > 0.95f ? vec3(0, 0, -1) : vec3(0, 1, 0);
    DepthMapSpec s;
    s.instance = i;
    s.members = members;
    s.index = k;
    s.reflector = reflector;
    s.centre = centre;
    s.radius = radius;
    s.from = glm::normalize(to_local * from);
    s.up = glm::normalize(to_local * up_world);
    specs.push_back(s);
  }
}

}  // namespace

std::vector<int> depthMappedObjects(const Scene& scene) {
  const SceneLayers layers = sceneLayers(scene);
  std::vector<int> objects;
  for (int i = 0; i < int(scene.instances.size()); ++i)
    if (!scene.isReflector(i) && !layers.environment(i) &&
        !isPlanarInstance(scene, i, scene.instances[size_t(i)].matrixAt(0.0f)))
      objects.push_back(i);
  return objects;
}

std::vector<DepthMapSpec> placeDepthMaps(const Scene& scene, const DepthMapOptions& options,
                                         const std::vector<std::vector<int>>& groups) {
  const float time = 0.0f;
  vec3 centroid(0.0f);
  const std::vector<int> reflectors = scene.reflectorInstances();
  for (int r : reflectors)
    centroid += scene.instanceBounds(r, time).center() / float(reflectors.size());
  std::vector<DepthMapSpec> specs;
  std::vector<std::vector<int>> lists = groups;
  if (lists.empty())
    for (int i : depthMappedObjects(scene)) lists.push_back({i});
  for (const std::vector<int>& group : lists) {
    const int i = group.front();
    const std::vector<int> members(group.begin() + 1, group.end());
    placeMaps(scene, i, members, scene.instances[size_t(i)].matrixAt(time), centroid, options.maps,
              false, specs);
  }
  if (options.self_maps > 0) {
    const vec3 eye = scene.camera().position;
    for (int r : reflectors) {
      const mat4 model = scene.instances[size_t(r)].matrixAt(time);
      if (isPlanarInstance(scene, r, model)) continue;  // a plane never sees itself
      placeMaps(scene, r, {}, model, eye, options.self_maps, true, specs);
    }
  }
  return specs;
}

std::vector<int> depthMappedInstances(const std::vector<DepthMapSpec>& specs) {
  std::vector<int> out;
  for (const DepthMapSpec& s : specs)
    if (!s.reflector && s.index == 0) {
      out.push_back(s.instance);
      out.insert(out.end(), s.members.begin(), s.members.end());
    }
  return out;
}

vec4 depthMapSphere(const DepthMapSpec& spec, const mat4& model) {
  const mat3 linear(model);
  // A rigid motion with uniform scale keeps the sphere a sphere; the largest axis scale bounds it
  // otherwise.
  const float scale =
      std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]), 1e-12f});
  return vec4(transformPoint(model, spec.centre), 1.01f * spec.radius * scale);
}

View depthMapView(const DepthMapSpec& spec, const mat4& model, const DepthMapOptions& options) {
  const mat3 linear(model);
  const vec4 sphere = depthMapSphere(spec, model);
  const float radius = sphere.w;
  const vec3 centre = vec3(sphere);
  const vec3 from = glm::normalize(linear * spec.from);
  const float distance = radius / std::sin(glm::radians(options.fov_degrees) * 0.5f);
  CameraDesc c;
  c.name = "depth map";
  c.position = centre + from * distance;
  c.target = centre;
  c.up = glm::normalize(linear * spec.up);
  c.fov_y_degrees = options.fov_degrees;
  c.near_plane = std::max(distance - radius, 1e-3f * distance);
  c.far_plane = distance + radius;
  return View(c, ivec2(options.size));
}

}  // namespace mirage
