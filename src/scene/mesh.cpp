#include "scene/mesh.h"

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
    if (!isFinite(positions[i])) throwInput("{}: vertex {} has a non-finite position", who, i);
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

}  // namespace mirage
