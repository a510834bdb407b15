// Procedural meshes for the built-in scenes and the tests (no downloads needed).
// All have normals and texture coordinates; sizes are in scene units.
#pragma once

#include <vector>

#include "scene/mesh.h"

namespace mirage::procedural {

// A UV sphere centred at the origin with analytic normals.
Mesh sphere(float radius, int segments = 96, int rings = 48);
// An axis-aligned box centred at the origin with flat faces; `inward` turns it into a room.
Mesh box(const vec3& half_extent, bool inward = false);
// A quad in the XZ plane centred at the origin, normal +Y, uv = position / cell size, split into
// cells_x × cells_z squares (a grid, for surfaces that deform).
Mesh quad(float width, float depth, float uv_per_unit = 1.0f, int cells_x = 1, int cells_z = 1);
// A capped cylinder along +Y from y = 0 to y = height.
Mesh cylinder(float radius, float height, int segments = 48);
// A surface of revolution about +Y through the (radius, y) profile points, bottom to top.
Mesh lathe(const std::vector<vec2>& profile, int segments = 64);
// A torus in the XY plane around the origin.
Mesh torus(float major_radius, float minor_radius, int segments = 48, int sides = 24);
// A square pyramid standing on its apex at the origin (the base at y = height), or upright.
Mesh pyramid(float base_half_width, float height, bool inverted);
// A teapot-like object (lathe body, lid knob, torus handle, conical spout), about 1 unit tall,
// standing on y = 0. Stands in for the Utah teapot where no asset is fetched.
Mesh teapotLike(int segments = 48);

// Appends `part`, transformed by `m`, to `mesh`.
void append(Mesh& mesh, Mesh part, const mat4& m = mat4(1.0f));

}  // namespace mirage::procedural
