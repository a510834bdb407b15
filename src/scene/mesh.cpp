#include "scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <unordered_map>

#include <tbb/parallel_sort.h>

#include "core/error.h"

namespace mirage {

Bounds3 Mesh::bounds() const {
  Bounds3 b;
  for (const vec3& p : positions) b.extend(p);
  return b;
}

void Mesh::computeNormals() {
  normals.assign(positions.size(), vec3(0.0f));
  for (const uvec3& t : triangles) {
    vec3 a = positions[t.x], b = positions[t.y], c = positions[t.z];
    vec3 n = glm::cross(b - a, c - a);  // length = 2 * area: area weighting
    normals[t.x] += n;
    normals[t.y] += n;
    normals[t.z] += n;
  }
  for (vec3& n : normals) {
    float len = glm::length(n);
    n = len > 0.0f ? n / len : vec3(0.0f, 1.0f, 0.0f);
  }
}

void Mesh::computeTangents() {
  if (uvs.size() != positions.size() || normals.size() != positions.size()) return;
  std::vector<vec3> tan(positions.size(), vec3(0.0f)), bitan(positions.size(), vec3(0.0f));
  for (const uvec3& t : triangles) {
    vec3 e1 = positions[t.y] - positions[t.x], e2 = positions[t.z] - positions[t.x];
    vec2 d1 = uvs[t.y] - uvs[t.x], d2 = uvs[t.z] - uvs[t.x];
    float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-12f) continue;
    float r = 1.0f / det;
    vec3 sdir = (e1 * d2.y - e2 * d1.y) * r;
    vec3 tdir = (e2 * d1.x - e1 * d2.x) * r;
    for (unsigned i : {t.x, t.y, t.z}) {
      tan[i] += sdir;
      bitan[i] += tdir;
    }
  }
  tangents.resize(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    vec3 n = normals[i];
    vec3 t = tan[i] - n * glm::dot(n, tan[i]);
    if (glm::length(t) < 1e-12f) {
      t = glm::cross(n, std::abs(n.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0));
    }
    t = glm::normalize(t);
    float w = glm::dot(glm::cross(n, t), bitan[i]) < 0.0f ? -1.0f : 1.0f;
    tangents[i] = vec4(t, w);
  }
}

void Mesh::validate() const {
  const std::string& who = source.empty() ? name : source;
  if (positions.empty() || triangles.empty())
    throwInput("{}: mesh has no triangles ({} vertices, {} triangles)", who, positions.size(),
               triangles.size());
  if (!normals.empty() && normals.size() != positions.size())
    throwInput("{}: {} normals for {} vertices", who, normals.size(), positions.size());
  if (!uvs.empty() && uvs.size() != positions.size())
    throwInput("{}: {} texture coordinates for {} vertices", who, uvs.size(), positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
    if (!isFinite(positions[i]))
      throwInput("{}: vertex {} has a non-finite position ({}, {}, {}); positions must be finite",
                 who, i, positions[i].x, positions[i].y, positions[i].z);
  for (size_t i = 0; i < uvs.size(); ++i)
    if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y))
      throwInput("{}: vertex {} has non-finite texture coordinates ({}, {})", who, i, uvs[i].x,
                 uvs[i].y);
  const size_t n = positions.size();
  for (size_t i = 0; i < triangles.size(); ++i) {
    const uvec3& t = triangles[i];
    if (t.x >= n || t.y >= n || t.z >= n)
      throwInput("{}: triangle {} refers to vertex {} but there are only {} (allowed 0..{})", who,
                 i, std::max({t.x, t.y, t.z}), n, n - 1);
  }
}

void Mesh::transform(const mat4& m) {
  mat3 nm = normalMatrix(m);
  for (vec3& p : positions) p = transformPoint(m, p);
  for (vec3& nrm : normals) nrm = glm::normalize(nm * nrm);
  for (vec4& t : tangents) t = vec4(glm::normalize(mat3(m) * vec3(t)), t.w);
  // A mirroring transform flips the winding; keep the front faces front.
  if (glm::determinant(mat3(m)) < 0.0f)
    for (uvec3& t : triangles) std::swap(t.y, t.z);
}

Mesh subdivideMidpoint(const Mesh& mesh) {
  const std::string& who = mesh.source.empty() ? mesh.name : mesh.source;
  const size_t n = mesh.positions.size();
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const uvec3& t = mesh.triangles[i];
    if (t.x >= n || t.y >= n || t.z >= n)
      throwInput("{}: triangle {} refers to vertex {} but there are only {}", who, i,
                 std::max({t.x, t.y, t.z}), n);
  }
  // At most 3T new vertices; indices are 32 bits.
  if (uint64_t(n) + 3 * uint64_t(mesh.triangles.size()) > std::numeric_limits<uint32_t>::max())
    throwInput("{}: {} vertices and {} triangles are too many to subdivide", who, n,
               mesh.triangles.size());
  const bool has_normals = mesh.normals.size() == n;
  const bool has_uvs = mesh.uvs.size() == n;
  const bool has_tangents = mesh.tangents.size() == n;
  Mesh out;
  out.name = mesh.name;
  out.source = mesh.source;
  out.positions = mesh.positions;
  if (has_normals) out.normals = mesh.normals;
  if (has_uvs) out.uvs = mesh.uvs;
  if (has_tangents) out.tangents = mesh.tangents;
  out.triangles.reserve(mesh.triangles.size() * 4);

  // One midpoint per undirected edge, keyed by its sorted vertex pair.
  std::unordered_map<uint64_t, uint32_t> midpoints;
  midpoints.reserve(mesh.triangles.size() * 2);
  auto midpoint = [&](uint32_t a, uint32_t b, const vec3& face_normal) {
    uint64_t key = (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b));
    auto [it, inserted] = midpoints.try_emplace(key, uint32_t(out.positions.size()));
    if (!inserted) return it->second;
    out.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
    if (has_normals) {
      vec3 sum = mesh.normals[a] + mesh.normals[b];
      float len = glm::length(sum);
      out.normals.push_back(len > 1e-12f ? sum / len : face_normal);
    }
    if (has_uvs) out.uvs.push_back(0.5f * (mesh.uvs[a] + mesh.uvs[b]));
    if (has_tangents) {
      const vec4 &ta = mesh.tangents[a], &tb = mesh.tangents[b];
      vec3 t = vec3(ta) + vec3(tb);
      float len = glm::length(t);
      out.tangents.push_back(vec4(len > 1e-12f ? t / len : vec3(ta), ta.w));
    }
    return it->second;
  };

  for (const uvec3& t : mesh.triangles) {
    vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
    vec3 face = glm::cross(b - a, c - a);
    float len = glm::length(face);
    face = len > 0.0f ? face / len : vec3(0.0f, 1.0f, 0.0f);
    uint32_t ab = midpoint(t.x, t.y, face), bc = midpoint(t.y, t.z, face),
             ca = midpoint(t.z, t.x, face);
    out.triangles.push_back({t.x, ab, ca});
    out.triangles.push_back({ab, t.y, bc});
    out.triangles.push_back({ca, bc, t.z});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

double boundaryEdgeFraction(const Mesh& mesh) {
  if (mesh.triangles.empty()) return 0.0;
  // Weld positions that round to the same cell of a grid 1e-5 of the mesh's size: generated
  // seams differ by rounding (sin 2π is not 0). Two positions straddling a cell wall stay apart;
  // at a few in 10^5 that moves the fraction by nothing that matters.
  const Bounds3 box = mesh.bounds();
  const float cell = std::max(1e-5f * glm::length(box.extent()), 1e-30f);
  struct Keyed {
    glm::i64vec3 cell;
    uint32_t index;
    bool operator<(const Keyed& o) const {
      return std::tie(cell.x, cell.y, cell.z, index) <
             std::tie(o.cell.x, o.cell.y, o.cell.z, o.index);
    }
  };
  std::vector<Keyed> keyed(mesh.positions.size());
  for (uint32_t i = 0; i < uint32_t(keyed.size()); ++i)
    keyed[i] = {glm::i64vec3(glm::round(glm::dvec3(mesh.positions[i] - box.lo) / double(cell))), i};
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> weld(mesh.positions.size());
  for (size_t i = 0; i < keyed.size(); ++i)
    weld[keyed[i].index] =
        i > 0 && keyed[i].cell == keyed[i - 1].cell ? weld[keyed[i - 1].index] : keyed[i].index;
  // Every edge as (low, high) welded indices, sorted: equal keys are one edge's uses.
  std::vector<uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (const uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = weld[t[k]], c = weld[t[(k + 1) % 3]];
      if (a == c) continue;  // a collapsed edge bounds nothing
      if (a > c) std::swap(a, c);
      edges.push_back((uint64_t(a) << 32) | c);
    }
  tbb::parallel_sort(edges.begin(), edges.end());
  size_t distinct = 0, boundary = 0;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    ++distinct;
    boundary += j - i == 1 ? 1 : 0;
    i = j;
  }
  return distinct == 0 ? 0.0 : double(boundary) / double(distinct);
}

}  // namespace mirage
