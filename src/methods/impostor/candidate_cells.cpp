#include "methods/impostor/candidate_cells.h"

#include <algorithm>
#include <cmath>

#include "methods/impostor/billboard_shared.h"

namespace mirage {

namespace {

// The direction through (u, v) in [-1, 1]^2 of cube face `face` (direction_cell's faces).
vec3 faceDirection(int face, float u, float v) {
  const float s = (face % 2 == 0) ? 1.0f : -1.0f;
  switch (face / 2) {
    case 0:
      return glm::normalize(vec3(s, u, v));
    case 1:
      return glm::normalize(vec3(v, s, u));
    default:
      return glm::normalize(vec3(u, v, s));
  }
}

float angleBetween(const vec3& a, const vec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

// The largest stretch of a linear map: the largest column norm when the columns are orthogonal
// (rotation and scale), else the Frobenius norm, which bounds it.
float largestStretch(const mat3& m) {
  const float a = glm::length(m[0]), b = glm::length(m[1]), c = glm::length(m[2]);
  const float tolerance = 1e-5f * (a * a + b * b + c * c);
  const bool orthogonal = std::abs(glm::dot(m[0], m[1])) <= tolerance &&
                          std::abs(glm::dot(m[1], m[2])) <= tolerance &&
                          std::abs(glm::dot(m[0], m[2])) <= tolerance;
  return orthogonal ? std::max({a, b, c}) : std::sqrt(a * a + b * b + c * c);
}

}  // namespace

DirectionCone directionCellCone(int cell, int g) {
  if (g <= 0) return {};
  const int face = cell / (g * g), in_face = cell % (g * g);
  const int col = in_face % g, row = in_face / g;
  auto coordinate = [g](int i) { return -1.0f + 2.0f * float(i) / float(g); };
  DirectionCone cone;
  cone.axis = faceDirection(face, 0.5f * (coordinate(col) + coordinate(col + 1)),
                            0.5f * (coordinate(row) + coordinate(row + 1)));
  // A cell is a convex spherical quadrilateral (its sides are great circles): its farthest
  // point from the axis is a corner.
  cone.half_angle = 0.0f;
  for (int corner = 0; corner < 4; ++corner) {
    const vec3 d =
        faceDirection(face, coordinate(col + (corner & 1)), coordinate(row + corner / 2));
    cone.half_angle = std::max(cone.half_angle, angleBetween(cone.axis, d));
  }
  // Rounding: the cell lookup in float may place a direction on a border in either cell.
  cone.half_angle += 1e-4f;
  cone.cos_half = std::cos(cone.half_angle);
  cone.sin_half = std::sin(cone.half_angle);
  return cone;
}

bool mayReach(const BoundingSphere& from, const DirectionCone& cone, const BoundingSphere& to) {
  if (cone.half_angle >= kPi) return true;
  const vec3 between = to.centre - from.centre;
  const float distance = glm::length(between);
  const float reach = from.radius + to.radius;
  if (distance <= reach) return true;
  // angle(axis, between) <= half + asin(reach / distance), as cosines (both sides below pi).
  const float sin_grown = reach / distance, cos_grown = std::sqrt(1.0f - sin_grown * sin_grown);
  const float cos_limit = cone.cos_half * cos_grown - cone.sin_half * sin_grown;
  return glm::dot(cone.axis, between) >= cos_limit * distance - 1e-6f * distance;
}

BoundingSphere vertexSphere(const Scene& scene, int instance, float time) {
  const Instance& inst = scene.instances[size_t(instance)];
  const Mesh& mesh = scene.meshes[size_t(inst.mesh)];
  const mat4 m = inst.matrixAt(time);
  const Bounds3 local = scene.localBounds(instance);
  BoundingSphere s;
  if (local.empty()) return s;
  s.centre = transformPoint(m, local.center());
  const mat3 linear(m);
  float squared = 0.0f;
  for (const vec3& p : mesh.positions) {
    const vec3 d = linear * (p - local.center());
    squared = std::max(squared, glm::dot(d, d));
  }
  s.radius = std::sqrt(squared) + inst.deformation.maxDisplacement() * largestStretch(linear);
  return s;
}

BoundingSphere coveredSphere(const BoundingSphere& object, float distance, float texel) {
  const float ratio = std::min(object.radius / std::max(distance, 1e-30f), 0.999f);
  BoundingSphere covered = object;
  covered.radius = object.radius / std::sqrt(1.0f - ratio * ratio) + std::sqrt(2.0f) * texel;
  // Slack for the float arithmetic of the capture and of the quad the rays test.
  covered.radius *= 1.01f;
  return covered;
}

std::vector<BoundingSphere> reflectorVertexSpheres(const Scene& scene, float time) {
  std::vector<BoundingSphere> spheres;
  for (int instance : scene.reflectorInstances())
    spheres.push_back(vertexSphere(scene, instance, time));
  return spheres;
}

CellLists cellLists(const std::vector<BoundingSphere>& origins, int g,
                    const std::vector<BoundingSphere>& spheres, const std::vector<int>& owner) {
  CellLists lists;
  const int cells = shading::direction_cell_count(g);
  for (int r = 0; r < int(origins.size()); ++r)
    for (int cell = 0; cell < cells; ++cell) {
      const DirectionCone cone = directionCellCone(cell, g);
      const int first = int(lists.entries.size());
      for (int i = 0; i < int(spheres.size()); ++i) {
        const bool listed = owner[size_t(i)] >= 0
                                ? owner[size_t(i)] == r
                                : mayReach(origins[size_t(r)], cone, spheres[size_t(i)]);
        if (listed) lists.entries.push_back(i);
      }
      lists.ranges.push_back(ivec2(first, int(lists.entries.size()) - first));
    }
  return lists;
}

}  // namespace mirage
