#include "methods/hybrid/point_set.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <tbb/parallel_for.h>

#include "methods/hybrid/point_spacing.h"
#include "shading/shading.h"

namespace mirage {

namespace {

// Uniform candidates a stratified sample is chosen from, and the largest spacing a point may take
// from its neighbourhood, in mean spacings.
constexpr size_t kCandidatesPerSample = 2;
constexpr float kMostSpacing = 4.0f;

vec3 albedoAt(const Scene& scene, const Material& material, vec2 uv) {
  vec3 albedo = shading::material_albedo(material.gpuData(), uv);
  if (material.albedo_texture >= 0)
    albedo *= sampleTexture(scene.textures[size_t(material.albedo_texture)].image, uv);
  return albedo;
}

// Triangle areas as a running sum (for sampling a triangle in proportion to its area).
std::vector<double> areaCdf(const Mesh& mesh, const mat4& model) {
  std::vector<double> cdf(mesh.triangleCount());
  double sum = 0.0;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uvec3 tri = mesh.triangles[t];
    vec3 a = vec3(model * vec4(mesh.positions[tri.x], 1.0f));
    vec3 b = vec3(model * vec4(mesh.positions[tri.y], 1.0f));
    vec3 c = vec3(model * vec4(mesh.positions[tri.z], 1.0f));
    sum += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    cdf[t] = sum;
  }
  return cdf;
}

void addVertices(const Scene& scene, const Mesh& mesh, const Material& material, PointSet& set) {
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    // Vertices no triangle uses (a lathe's axis points) have no normal: not on the surface.
    const vec3 n = mesh.normals[v];
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) || glm::dot(n, n) < 0.5f)
      continue;
    set.positions.push_back(mesh.positions[v]);
    set.normals.push_back(mesh.normals[v]);
    vec2 uv = mesh.uvs.empty() ? vec2(0.0f) : mesh.uvs[v];
    set.albedo.push_back(albedoAt(scene, material, uv));
  }
  set.vertex_points = set.positions.size();
}

// `count` points uniform over the surface (by world area), deterministic for a seed: blocks of
// points draw from their own generators, so the result does not depend on the thread count.
void addSurfaceSamples(const Scene& scene, const Mesh& mesh, const Material& material,
                       const std::vector<double>& cdf, size_t count, uint32_t seed, PointSet& set) {
  const size_t first = set.positions.size();
  set.positions.resize(first + count);
  set.normals.resize(first + count);
  set.albedo.resize(first + count);
  constexpr size_t kBlock = 4096;
  const double total = cdf.back();
  tbb::parallel_for(size_t(0), (count + kBlock - 1) / kBlock, [&](size_t block) {
    std::mt19937 rng(seed * 7919u + uint32_t(block));
    std::uniform_real_distribution<double> pick(0.0, total);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (size_t i = block * kBlock; i < std::min(count, (block + 1) * kBlock); ++i) {
      size_t t = size_t(std::upper_bound(cdf.begin(), cdf.end(), pick(rng)) - cdf.begin());
      t = std::min(t, cdf.size() - 1);
      const uvec3 tri = mesh.triangles[t];
      float s = std::sqrt(unit(rng)), r = unit(rng);
      vec3 w(1.0f - s, s * (1.0f - r), s * r);
      size_t o = first + i;
      set.positions[o] =
          w.x * mesh.positions[tri.x] + w.y * mesh.positions[tri.y] + w.z * mesh.positions[tri.z];
      vec3 n = w.x * mesh.normals[tri.x] + w.y * mesh.normals[tri.y] + w.z * mesh.normals[tri.z];
      if (glm::dot(n, n) < 1e-20f)
        n = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                       mesh.positions[tri.z] - mesh.positions[tri.x]);
      set.normals[o] = glm::dot(n, n) > 0.0f ? glm::normalize(n) : vec3(0.0f, 1.0f, 0.0f);
      vec2 uv = mesh.uvs.empty()
                    ? vec2(0.0f)
                    : w.x * mesh.uvs[tri.x] + w.y * mesh.uvs[tri.y] + w.z * mesh.uvs[tri.z];
      set.albedo[o] = albedoAt(scene, material, uv);
    }
  });
}

// `count` points stratified over the surface, appended after the `set.size()` already there
// (its mesh vertices, which stay): kCandidatesPerSample times as many uniform samples, thinned
// to a Poisson-disk set by sample elimination (point_spacing.h) on the object's `area`.
void addStratifiedSamples(const Scene& scene, const Mesh& mesh, const Material& material,
                          const std::vector<double>& cdf, size_t count, double area, uint32_t seed,
                          PointSet& set) {
  const size_t fixed = set.size();
  addSurfaceSamples(scene, mesh, material, cdf, count * kCandidatesPerSample, seed, set);
  const std::vector<uint32_t> kept = eliminateSamples(set.positions, fixed, fixed + count, area);
  set.permute(kept);
}

template <typename T>
void permuteVector(std::vector<T>& v, const std::vector<uint32_t>& order) {
  std::vector<T> out(order.size());
  for (size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
  v = std::move(out);
}

}  // namespace

void PointSet::permute(const std::vector<uint32_t>& order) {
  permuteVector(positions, order);
  permuteVector(normals, order);
  permuteVector(albedo, order);
  if (!spacings.empty()) permuteVector(spacings, order);
}

std::vector<int> pointSampledInstances(const Scene& scene) {
  const SceneLayers layers = sceneLayers(scene);
  std::vector<int> out;
  for (int i = 0; i < int(scene.instances.size()); ++i)
    if (!scene.isReflector(i) && !layers.environment(i) &&
        !isPlanarInstance(scene, i, mat4(1.0f)))
      out.push_back(i);
  return out;
}

std::vector<PointSet> samplePoints(const Scene& scene, const std::vector<int>& instances,
                                   const PointSetOptions& options) {
  std::vector<std::vector<double>> cdfs;
  double area = 0.0;
  for (int i : instances) {
    const Instance& inst = scene.instances[size_t(i)];
    cdfs.push_back(areaCdf(scene.meshes[size_t(inst.mesh)], inst.matrixAt(0.0f)));
    area += cdfs.back().empty() ? 0.0 : cdfs.back().back();
  }
  long long total = options.total;
  if (total <= 0 && options.minimum > 0) {
    // Vertices alone are too sparse on low-polygon objects: top them up by area.
    long long vertices = 0;
    for (int i : instances)
      vertices += (long long)scene.meshes[size_t(scene.instances[size_t(i)].mesh)].vertexCount();
    if (vertices < options.minimum) total = options.minimum;
  }
  std::vector<PointSet> sets;
  std::map<int, bool> closed_meshes;  // mesh index -> closed surface
  long long assigned = 0;
  for (size_t k = 0; k < instances.size(); ++k) {
    const Instance& inst = scene.instances[size_t(instances[k])];
    const Mesh& mesh = scene.meshes[size_t(inst.mesh)];
    const Material& material = scene.materials[size_t(inst.material)];
    PointSet set;
    set.instance = instances[k];
    const double own = cdfs[k].empty() ? 0.0 : cdfs[k].back();
    const std::vector<double> object = areaCdf(mesh, mat4(1.0f));
    const double object_area = object.empty() ? 0.0 : object.back();
    if (total <= 0) {
      addVertices(scene, mesh, material, set);
    } else if (own > 0.0) {
      // The last object takes the remainder, so the total is exact.
      long long share = k + 1 == instances.size()
                            ? total - assigned
                            : std::llround(double(total) * own / std::max(area, 1e-30));
      share = std::clamp(share, 0LL, total - assigned);
      assigned += share;
      size_t samples = size_t(share);
      if (share >= (long long)mesh.vertexCount()) {
        addVertices(scene, mesh, material, set);
        samples -= set.size();
      }
      addStratifiedSamples(scene, mesh, material, cdfs[k], samples, object_area,
                           options.seed + uint32_t(k), set);
    }
    if (set.size() > 0) {
      set.spacing = float(std::sqrt(object_area / double(set.size())));
      set.spacings = neighbourSpacings(set.positions, set.spacing, kMostSpacing * set.spacing);
      // Scanned meshes keep a few small holes; through them one sees only a sliver of inside.
      const int mesh_index = scene.instances[size_t(instances[k])].mesh;
      auto [known, added] = closed_meshes.try_emplace(mesh_index, false);
      if (added) known->second = boundaryEdgeFraction(mesh) <= 0.01;  // once per mesh
      set.closed = known->second;
      sets.push_back(std::move(set));
    }
  }
  return sets;
}

}  // namespace mirage
