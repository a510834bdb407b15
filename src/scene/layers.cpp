#include "scene/layers.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/bounds.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace mirage {

namespace {

// A plane being gathered: its normal and offset (from its first triangle) and its triangles.
struct PlaneCluster {
  vec3 normal{0.0f};
  float offset = 0.0f;
  float area = 0.0f;
  std::vector<int> triangles;
};

// The triangle's unit normal facing its vertex normals' side (a winding that disagrees with the
// normals is the file's mistake, not the surface's), its area; false when degenerate.
bool triangleFacing(const Mesh& mesh, const uvec3& t, vec3& normal, float& area) {
  const vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
  const vec3 n = glm::cross(b - a, c - a);
  const float twice = glm::length(n);
  if (!(twice > 0.0f) || !std::isfinite(twice)) return false;
  normal = n / twice;
  area = 0.5f * twice;
  if (mesh.normals.size() == mesh.positions.size()) {
    const vec3 shading = mesh.normals[t.x] + mesh.normals[t.y] + mesh.normals[t.z];
    if (glm::dot(shading, normal) < 0.0f) normal = -normal;
  }
  return true;
}

// The extent of the cluster's vertices along u and v = n x u.
void extentAlong(const Mesh& mesh, const PlaneCluster& c, const vec3& u, vec2& lo, vec2& hi) {
  const vec3 v = glm::cross(c.normal, u);
  lo = vec2(1e30f);
  hi = vec2(-1e30f);
  for (int t : c.triangles)
    for (int k = 0; k < 3; ++k) {
      const vec3 p = mesh.positions[mesh.triangles[size_t(t)][k]];
      const vec2 q(glm::dot(p, u), glm::dot(p, v));
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
}

// The rectangle in the cluster's plane that holds its triangles: of the directions of its
// triangles' edges (the first 16 triangles'), the one whose rectangle is the smallest (a face's
// side, not its diagonal).
PlanarPart rectangleOf(const Mesh& mesh, const PlaneCluster& c) {
  const vec3 n = c.normal;
  vec3 best_u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0)));
  vec2 best_lo, best_hi;
  extentAlong(mesh, c, best_u, best_lo, best_hi);
  float best_area = (best_hi.x - best_lo.x) * (best_hi.y - best_lo.y);
  for (size_t i = 0; i < std::min<size_t>(c.triangles.size(), 16); ++i) {
    const uvec3& tri = mesh.triangles[size_t(c.triangles[i])];
    for (int k = 0; k < 3; ++k) {
      vec3 u = mesh.positions[tri[(k + 1) % 3]] - mesh.positions[tri[k]];
      u -= glm::dot(u, n) * n;
      if (!(glm::length(u) > 0.0f)) continue;
      u = glm::normalize(u);
      vec2 lo, hi;
      extentAlong(mesh, c, u, lo, hi);
      const float area = (hi.x - lo.x) * (hi.y - lo.y);
      if (area < best_area * (1.0f - 1e-5f)) {
        best_area = area;
        best_u = u;
        best_lo = lo;
        best_hi = hi;
      }
    }
  }
  const vec3 v = glm::cross(n, best_u);
  PlanarPart part;
  part.normal = n;
  part.corner = best_lo.x * best_u + best_lo.y * v + c.offset * n;
  part.edge_u = (best_hi.x - best_lo.x) * best_u;
  part.edge_v = (best_hi.y - best_lo.y) * v;
  part.area = c.area;
  part.triangles = int(c.triangles.size());
  return part;
}

bool contains(const Bounds3& outer, const Bounds3& inner, float tolerance) {
  return glm::all(glm::lessThanEqual(outer.lo - tolerance, inner.lo)) &&
         glm::all(glm::lessThanEqual(inner.hi, outer.hi + tolerance));
}

// The default rule for diffuse instance i (see layers.h); reflectors' bounds and neighbourhood
// at time 0.
InstanceLayer defaultLayer(const Scene& scene, int i, const std::vector<int>& reflectors,
                           const Bounds3& neighbourhood) {
  InstanceLayer l;
  if (reflectors.empty()) {
    l.why = "no reflectors";
    return l;
  }
  if (!scene.instances[size_t(i)].animation.empty()) {
    l.why = "animated";
    return l;
  }
  const Bounds3 b = scene.instanceBounds(i, 0.0f);
  for (int r : reflectors) {
    const Bounds3 rb = scene.instanceBounds(r, 0.0f);
    if (contains(b, rb, 1e-4f * b.radius())) {
      l.layer = Layer::kEnvironment;
      l.why = fmt::format("holds reflector '{}'", scene.instances[size_t(r)].name);
      return l;
    }
  }
  const float ratio = b.radius() / std::max(neighbourhood.radius(), 1e-6f);
  if (ratio > kEnvironmentSizeFactor) {
    l.layer = Layer::kEnvironment;
    l.why = fmt::format("{:.1f}x the reflectors' neighbourhood (beyond {:g}x)", ratio,
                        kEnvironmentSizeFactor);
    return l;
  }
  l.why = fmt::format("compact ({:.1f}x the reflectors' neighbourhood)", ratio);
  return l;
}

}  // namespace

std::vector<PlanarPart> planarParts(const Mesh& mesh, float* rest_area) {
  const float size = std::max(mesh.bounds().radius(), 1e-12f);
  const float offset_tolerance = 1e-4f * size;
  const float cos_tolerance = std::cos(glm::radians(1.0f));
  std::vector<PlaneCluster> clusters;
  float total = 0.0f, unclustered = 0.0f;
  for (int t = 0; t < int(mesh.triangles.size()); ++t) {
    const uvec3& tri = mesh.triangles[size_t(t)];
    vec3 n;
    float area;
    if (!triangleFacing(mesh, tri, n, area)) continue;
    total += area;
    const float offset = glm::dot(n, mesh.positions[tri.x]);
    PlaneCluster* home = nullptr;
    for (PlaneCluster& c : clusters)
      if (glm::dot(c.normal, n) > cos_tolerance && std::abs(c.offset - offset) <= offset_tolerance &&
          std::abs(glm::dot(c.normal, mesh.positions[tri.y]) - c.offset) <= offset_tolerance &&
          std::abs(glm::dot(c.normal, mesh.positions[tri.z]) - c.offset) <= offset_tolerance) {
        home = &c;
        break;
      }
    // A curved mesh would make a plane per triangle: beyond the cap, its triangles stay out.
    if (!home && int(clusters.size()) < 4 * kMaxPlanarParts) {
      PlaneCluster c;
      c.normal = n;
      c.offset = offset;
      clusters.push_back(std::move(c));
      home = &clusters.back();
    }
    if (!home) {
      unclustered += area;
      continue;
    }
    home->area += area;
    home->triangles.push_back(t);
  }
  std::stable_sort(clusters.begin(), clusters.end(),
                   [](const PlaneCluster& a, const PlaneCluster& b) { return a.area > b.area; });
  std::vector<PlanarPart> parts;
  float rest = unclustered;
  for (const PlaneCluster& c : clusters) {
    if (int(parts.size()) < kMaxPlanarParts && c.area >= kMinPartShare * total)
      parts.push_back(rectangleOf(mesh, c));
    else
      rest += c.area;
  }
  if (rest_area) *rest_area = rest;
  return parts;
}

std::vector<PlanarPart> SceneLayers::planesOf(int instance) const {
  std::vector<PlanarPart> out;
  for (const EnvironmentPlane& p : planes)
    if (p.instance == instance) out.push_back(p.part);
  return out;
}

std::vector<int> SceneLayers::environmentInstances() const {
  std::vector<int> out;
  for (int i = 0; i < int(instances.size()); ++i)
    if (environment(i)) out.push_back(i);
  return out;
}

const char* SceneLayers::name(int instance) const {
  const InstanceLayer& l = instances[size_t(instance)];
  return l.reflector ? "reflector" : choiceName<Layer>(kLayers, l.layer);
}

SceneLayers sceneLayers(const Scene& scene) {
  SceneLayers layers;
  const std::vector<int> reflectors = scene.reflectorInstances();
  Bounds3 neighbourhood;
  for (int r : reflectors) neighbourhood.extend(scene.instanceBounds(r, 0.0f));
  for (int i = 0; i < int(scene.instances.size()); ++i) {
    const Instance& instance = scene.instances[size_t(i)];
    InstanceLayer l;
    if (scene.isReflector(i)) {
      l.reflector = true;
      l.why = "reflector";
    } else if (instance.layer) {
      l.layer = *instance.layer;
      l.why = "the scene file";
    } else {
      l = defaultLayer(scene, i, reflectors, neighbourhood);
    }
    layers.instances.push_back(l);
    if (!layers.environment(i)) continue;
    float rest = 0.0f, planar = 0.0f;
    const std::vector<PlanarPart> parts = planarParts(scene.meshes[size_t(instance.mesh)], &rest);
    for (const PlanarPart& part : parts) {
      layers.planes.push_back({i, part});
      planar += part.area;
    }
    // What the planes leave (beyond a thousandth of the area) is seen through probes.
    if (parts.empty() || rest > 1e-3f * (rest + planar)) layers.rest.push_back(i);
  }
  return layers;
}

}  // namespace mirage
