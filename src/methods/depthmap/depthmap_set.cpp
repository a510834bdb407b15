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

// Appends `count` maps of instance i, the first looking from the point `viewer` (world, time 0).
void placeMaps(const Scene& scene, int i, const mat4& model, const vec3& viewer, int count,
               bool reflector, std::vector<DepthMapSpec>& specs) {
  const Bounds3 local = scene.localBounds(i);
  if (local.empty()) return;
  const vec3 world_centre = transformPoint(model, local.center());
  vec3 towards = viewer - world_centre;
  towards = glm::length(towards) > 1e-6f ? glm::normalize(towards) : vec3(0, 0, 1);
  const mat3 to_local = glm::inverse(mat3(model));
  const std::vector<vec3> dirs = mapDirections(towards);
  for (int k = 0; k < count; ++k) {
    const vec3 from = dirs[size_t(k)];
    const vec3 up_world = std::abs(from.y) > 0.95f ? vec3(0, 0, -1) : vec3(0, 1, 0);
    DepthMapSpec s;
    s.instance = i;
    s.index = k;
    s.reflector = reflector;
    s.centre = local.center();
    s.radius = std::max(local.radius(), 1e-6f);
    s.from = glm::normalize(to_local * from);
    s.up = glm::normalize(to_local * up_world);
    specs.push_back(s);
  }
}

}  // namespace

std::vector<DepthMapSpec> placeDepthMaps(const Scene& scene, const DepthMapOptions& options) {
  const float time = 0.0f;
  vec3 centroid(0.0f);
  const std::vector<int> reflectors = scene.reflectorInstances();
  for (int r : reflectors)
    centroid += scene.instanceBounds(r, time).center() / float(reflectors.size());
  std::vector<DepthMapSpec> specs;
  for (int i = 0; i < int(scene.instances.size()); ++i) {
    if (scene.isReflector(i)) continue;
    const mat4 model = scene.instances[size_t(i)].matrixAt(time);
    if (isPlanarInstance(scene, i, model)) continue;
    placeMaps(scene, i, model, centroid, options.maps, false, specs);
  }
  if (options.self_maps > 0) {
    const vec3 eye = scene.camera().position;
    for (int r : reflectors) {
      const mat4 model = scene.instances[size_t(r)].matrixAt(time);
      if (isPlanarInstance(scene, r, model)) continue;  // a plane never sees itself
      placeMaps(scene, r, model, eye, options.self_maps, true, specs);
    }
  }
  return specs;
}

std::vector<int> depthMappedInstances(const std::vector<DepthMapSpec>& specs) {
  std::vector<int> out;
  for (const DepthMapSpec& s : specs)
    if (!s.reflector && (out.empty() || out.back() != s.instance)) out.push_back(s.instance);
  return out;
}

View depthMapView(const DepthMapSpec& spec, const mat4& model, const DepthMapOptions& options) {
  const mat3 linear(model);
  // A rigid motion with uniform scale keeps the sphere a sphere; the largest axis scale bounds it
  // otherwise.
  const float scale =
      std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]), 1e-12f});
  const float radius = 1.01f * spec.radius * scale;
  const vec3 centre = transformPoint(model, spec.centre);
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
