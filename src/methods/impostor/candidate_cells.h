// Which impostors a reflected ray can reach, as the candidate lists per direction cell need it
// (--impostor-cells; billboard_shared.h: direction_cell). A reflector's rays start inside its
// bounding sphere; a billboard can only be hit where its coverage passes the alpha test, which
// is inside a sphere around what it stands for. A ray from a sphere O along a direction of a
// cone C can reach a sphere T only if the angle between C's axis and the line between the
// centres is at most C's half-angle plus the angular radius of T grown by O, seen from O's
// centre: asin((r_O + r_T) / distance). That test keeps every billboard a ray of the cell can
// hit and drops the others from the cell's list.
#pragma once

#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace mirage {

struct BoundingSphere {
  vec3 centre{0.0f};
  float radius = 0.0f;
};

// The directions of one cell: every direction of the cell is within half_angle of axis.
struct DirectionCone {
  vec3 axis{0.0f, 0.0f, 1.0f};
  float half_angle = kPi;  // radians; pi: every direction (else below pi / 2)
  float cos_half = -1.0f, sin_half = 0.0f;
};

// Cell `cell` of direction_cell with g cells a face edge (g = 0: the one cell, every direction).
DirectionCone directionCellCone(int cell, int g);

// Whether a ray starting inside `from` along a direction of `cone` can meet `to` (conservative:
// false only when none can).
bool mayReach(const BoundingSphere& from, const DirectionCone& cone, const BoundingSphere& to);

// A sphere around instance i's world bounding-box centre at `time` holding every vertex (a
// deforming instance's grown by its largest displacement): for a round object much tighter than
// the box's half-diagonal.
BoundingSphere vertexSphere(const Scene& scene, int instance, float time);

// Where a billboard's alpha test can pass, for a billboard that frames `object` (its vertex
// sphere) with a capture camera at `distance` from the sphere's centre and texels `texel` wide
// on the quad: the covered texels are the object's perspective projection onto the quad's plane
// through the centre, within radius / sqrt(1 - (radius / distance)^2) of it, and a texel
// counts as covered wherever any of its points is.
BoundingSphere coveredSphere(const BoundingSphere& object, float distance, float texel);

// The vertex spheres of the scene's reflectors at `time`, in reflector order: where their
// reflected rays start.
std::vector<BoundingSphere> reflectorVertexSpheres(const Scene& scene, float time);

// Candidate lists per reflector and direction cell, for impostors other than billboards:
// `ranges` holds (first, count) into `entries` for list billboard_list_index(r, dir, g), and
// the entries are candidate indices, in order.
struct CellLists {
  std::vector<ivec2> ranges;
  std::vector<int> entries;
};

// The lists of `origins.size()` reflectors with g cells a face edge: candidate i (its sphere
// `spheres[i]`) is in every list of reflector owner[i] when owner[i] >= 0 (a reflector's own
// impostor, for its own rays) and in no other; with owner[i] < 0, in the lists whose rays can
// reach it (mayReach).
CellLists cellLists(const std::vector<BoundingSphere>& origins, int g,
                    const std::vector<BoundingSphere>& spheres, const std::vector<int>& owner);

}  // namespace mirage
