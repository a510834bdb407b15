// Billboards as the shaders and the C++ code see them (the impostor paper, §3): the storage
// layout and the ray-billboard intersection. One copy of this code runs in billboard.frag and in
// the C++ tests; billboard_nearest_shared.h adds the alpha-tested nearest hit over a list.
#ifndef MIRAGE_METHODS_IMPOSTOR_BILLBOARD_SHARED_H
#define MIRAGE_METHODS_IMPOSTOR_BILLBOARD_SHARED_H

#include "shading/glsl_compat.h"
#include "shading/proxy.h"

// BillboardData.info.x
#define MIRAGE_BILLBOARD_DIFFUSE 0     // a textured quad: colour with coverage
#define MIRAGE_BILLBOARD_REFLECTIVE 1  // a reflector's quad: normal with coverage, and position

// Storage bindings and texture units of the billboard method.
#define MIRAGE_BIND_BILLBOARDS 5         // SSBO BillboardData[]
#define MIRAGE_BIND_BILLBOARD_RANGES 6   // SSBO BillboardRange[] (one per reflector)
#define MIRAGE_BIND_BILLBOARD_ENTRIES 7  // SSBO int[]: billboard indices the ranges point into
#define MIRAGE_BIND_IMPOSTOR_COUNTS 8    // SSBO uint[]: the frame's counts, in slots (below)
#define MIRAGE_BIND_BILLBOARD_CARRY 10   // SSBO BillboardCarry[] (one per billboard)
// The impostor trace's counts of the frame (atomics, one of each a pixel, in the slots of
// gpu/counter_slots_shared.h):
#define MIRAGE_IMPOSTOR_CANDIDATES 0  // impostors tested (billboards; depth-mapped objects)
#define MIRAGE_IMPOSTOR_RAYS 1        // reflected rays traced (one a bounce)
#define MIRAGE_IMPOSTOR_PIXELS 2      // reflector pixels shaded
#define MIRAGE_IMPOSTOR_COUNTS 3
// The surface array holds every billboard's coverage in alpha, so that the alpha test is one
// lookup whatever the kind: diffuse layers hold the colour (premultiplied by coverage),
// reflective layers the world-space normal.
#define MIRAGE_UNIT_BILLBOARD_SURFACE 4   // sampler2DArray, RGBA16F, mip-mapped
#define MIRAGE_UNIT_BILLBOARD_POSITION 6  // sampler2DArray: reflective surface points
#define MIRAGE_UNIT_BILLBOARD_ENV 7       // samplerCube: the environment reflections miss into

// Coverage at or above this counts as a hit (alpha test).
#define MIRAGE_BILLBOARD_ALPHA_CUTOFF 0.5f

SHARED_BEGIN

// One billboard: the quad corner + u * edge_u + v * edge_v, (u, v) in [0, 1]^2, with its texture
// (u, v) = (s, t) on layer info.y of the colour (diffuse) or normal/position (reflective) arrays.
struct BillboardData {
  vec4 corner;  // xyz: the corner at (u, v) = (0, 0); w: reflective: surface-point layer
  vec4 edge_u;  // xyz: the edge along u (perpendicular to edge_v); w: 1 / |edge_u|^2
  vec4 edge_v;  // xyz: the edge along v; w: 1 / |edge_v|^2
  vec4 plane;   // xyz: unit normal n = edge_u x edge_v / |...|; w: dot(n, corner)
  ivec4 info;   // x: MIRAGE_BILLBOARD_*; y: surface layer; z: the reflector a reflective
                // billboard stands for (0-based, -1 for diffuse); w: its material (-1)
};

// How a billboard kept from an earlier capture is carried by its object's motion since (the quad
// itself is carried on the CPU): a reflective billboard's stored surface points by the motion
// (the rows of its affine 3 x 4 matrix) and its stored normals by the motion's normal matrix
// (rows; the inverse transpose of its linear part). The identity for a fresh capture.
struct BillboardCarry {
  vec4 point_x, point_y, point_z;
  vec4 normal_x, normal_y, normal_z;
};

SHARED_FN vec3 billboard_carry_point(BillboardCarry c, vec3 p) {
  vec4 h = vec4(p, 1.0f);
  return vec3(dot(c.point_x, h), dot(c.point_y, h), dot(c.point_z, h));
}

SHARED_FN vec3 billboard_carry_normal(BillboardCarry c, vec3 n) {
  return vec3(dot(vec3(c.normal_x), n), dot(vec3(c.normal_y), n), dot(vec3(c.normal_z), n));
}

// Per reflector (0-based) and direction cell, which list entries its rays test: x, y: first entry
// and count of diffuse billboards; z, w: first entry and count of reflective billboards (never its
// own). The reflective entries follow the diffuse ones (z == x + y), so one loop can test both. A
// planar reflector has two lists: `range` for the rays that leave it towards the side its `plane`
// faces (dot(dir, n) >= 0), `back` for the others, each without the billboards that lie wholly on
// the far side of its plane; a curved one has one (`back` == `range`, plane 0).
struct BillboardRange {
  ivec4 range;
  ivec4 back;
  vec4 plane;  // xyz: unit normal n of a planar reflector (0 for a curved one); w: dot(n, point)
};

// The list that a ray leaving along `dir` tests.
SHARED_FN ivec4 billboard_list(BillboardRange lists, vec3 dir) {
  return dot(dir, vec3(lists.plane)) < 0.0f ? lists.back : lists.range;
}

// ray_quad (shading/proxy.h) with the plane and the inverse edge lengths precomputed: one
// division per test. Returns t > t_min, or -1 on a miss (uv is then undefined).
SHARED_FN float billboard_hit(BillboardData b, vec3 origin, vec3 dir, float t_min,
                              SHARED_OUT(vec2) uv) {
  vec3 n = vec3(b.plane);
  float denom = dot(dir, n);
  float t = (b.plane.w - dot(origin, n)) / (abs(denom) > 1.0e-12f ? denom : 1.0e-12f);
  vec3 local = origin + t * dir - vec3(b.corner);
  uv = vec2(dot(local, vec3(b.edge_u)) * b.edge_u.w, dot(local, vec3(b.edge_v)) * b.edge_v.w);
  bool inside = uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f;
  return (t > t_min && inside && abs(denom) > 1.0e-12f) ? t : -1.0f;
}

// Direction cells (--impostor-cells g): a reflector's lists are kept per cell of the directions
// its rays leave along, the cells of a cube map with g x g cells a face (6 g^2 in all; g = 0:
// one cell, every direction). A cell's list holds only the billboards that a ray leaving the
// reflector along a direction of the cell can reach (candidate_cells.h).
SHARED_FN int direction_cell_count(int g) {
  return g > 0 ? 6 * g * g : 1;
}

// The cell of direction `dir` (any length): face 0..5 (+x, -x, +y, -y, +z, -z), then the cell
// (column, row) of the face's (u, v) in [-1, 1]: +-x faces (y, z), +-y (z, x), +-z (x, y), each
// divided by the major component.
SHARED_FN int direction_cell(vec3 dir, int g) {
  if (g <= 0) return 0;
  vec3 a = abs(dir);
  int face = 0;
  vec2 uv = vec2(0.0f);
  float major = 1.0f;
  if (a.x >= a.y && a.x >= a.z) {
    face = dir.x >= 0.0f ? 0 : 1;
    uv = vec2(dir.y, dir.z);
    major = a.x;
  } else if (a.y >= a.z) {
    face = dir.y >= 0.0f ? 2 : 3;
    uv = vec2(dir.z, dir.x);
    major = a.y;
  } else {
    face = dir.z >= 0.0f ? 4 : 5;
    uv = vec2(dir.x, dir.y);
    major = a.z;
  }
  vec2 f = (uv / max(major, 1.0e-30f) * 0.5f + 0.5f) * float(g);
  ivec2 c = clamp(ivec2(floor(f)), ivec2(0), ivec2(g - 1));
  return face * g * g + c.y * g + c.x;
}

// The list of reflector `reflector` (0-based) that a ray leaving it along `dir` tests, among
// lists[] (direction_cell_count(g) per reflector).
SHARED_FN int billboard_list_index(int reflector, vec3 dir, int g) {
  return reflector * direction_cell_count(g) + direction_cell(dir, g);
}

// The data of the quad corner + u * edge_u + v * edge_v (u, v in [0, 1]).
SHARED_FN BillboardData make_billboard(vec3 corner, vec3 edge_u, vec3 edge_v, ivec4 info) {
  BillboardData b;
  vec3 n = normalize(cross(edge_u, edge_v));
  b.corner = vec4(corner, -1.0f);
  b.edge_u = vec4(edge_u, 1.0f / dot(edge_u, edge_u));
  b.edge_v = vec4(edge_v, 1.0f / dot(edge_v, edge_v));
  b.plane = vec4(n, dot(n, corner));
  b.info = info;
  return b;
}

// How (u, v) at the hit moves when the ray's origin moves by d_origin and its direction by
// d_dir (one pixel's ray differential): the footprint a mip-mapped lookup filters over.
SHARED_FN vec2 billboard_uv_differential(BillboardData b, vec3 dir, float t, vec3 d_origin,
                                         vec3 d_dir) {
  vec3 n = vec3(b.plane);
  vec3 dp = d_origin + t * d_dir;
  float dn = dot(dir, n);
  if (abs(dn) > 1.0e-20f) dp -= dir * (dot(dp, n) / dn);  // slide back onto the plane
  return vec2(dot(dp, vec3(b.edge_u)) * b.edge_u.w, dot(dp, vec3(b.edge_v)) * b.edge_v.w);
}

SHARED_END

#ifndef MIRAGE_GLSL
static_assert(sizeof(mirage::shading::BillboardData) == 5 * 16, "BillboardData layout");
static_assert(sizeof(mirage::shading::BillboardCarry) == 6 * 16, "BillboardCarry layout");
static_assert(sizeof(mirage::shading::BillboardRange) == 3 * 16, "BillboardRange layout");
#endif

#endif  // MIRAGE_METHODS_IMPOSTOR_BILLBOARD_SHARED_H
