// Triangle meshes as loaded or generated: positions, smooth normals, optional texture
// coordinates and tangents (for normal maps), 32-bit triangle indices.
#pragma once

#include <string>
#include <vector>

#include "core/bounds.h"
#include "core/math.h"

namespace mirage {

struct Mesh {
  std::string name;    // for messages and reports
  std::string source;  // the file it came from, or "builtin:<generator>"
  std::vector<vec3> positions;
  std::vector<vec3> normals;   // one per position, unit length
  std::vector<vec2> uvs;       // empty, or one per position
  std::vector<vec4> tangents;  // empty, or one per position (w: bitangent sign)
  std::vector<uvec3> triangles;

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return triangles.size(); }
  Bounds3 bounds() const;

  // Area-weighted smooth vertex normals (replaces any normals).
  void computeNormals();
  // Per-vertex tangents from the texture coordinates (needs uvs and normals).
  void computeTangents();
  // Checks indices, attribute counts and finiteness; throws InputError naming the mesh.
  void validate() const;
  // Applies an affine transform to positions, normals and tangents.
  void transform(const mat4& m);
};

// Midpoint subdivision: every triangle split into four at its edge midpoints, one new vertex per
// edge (shared by both triangles of a shared edge, so a closed mesh stays closed): V + E vertices,
// 4T triangles. Positions stay on the original flat triangles; midpoint normals are the
// normalised sum of the edge's end normals, uvs and tangents are interpolated. The original
// vertices keep their indices; triangle i becomes triangles 4i..4i+3 (its three corners, then the
// middle one), wound as it was. Throws InputError for an index out of range.
Mesh subdivideMidpoint(const Mesh& mesh);

// The fraction of the mesh's edges that only one triangle uses, with vertices at the same
// position (to 1e-5 of the mesh's size) welded first (seams in normals or uvs do not open a
// surface): 0 for a closed surface, 1 for a soup of separate triangles. An edge used by three or
// more triangles counts as closed.
double boundaryEdgeFraction(const Mesh& mesh);

}  // namespace mirage
