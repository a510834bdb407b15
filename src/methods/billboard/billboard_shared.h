// Billboards as the shaders and the C++ code see them (the impostor paper, §3): the storage
// layout and the ray-billboard intersection. One copy of this code runs in billboard.frag and in
// the C++ tests; billboard_nearest_shared.h adds the alpha-tested nearest hit over a list.
#ifndef MIRAGE_METHODS_BILLBOARD_BILLBOARD_SHARED_H
#define MIRAGE_METHODS_BILLBOARD_BILLBOARD_SHARED_H

#include "shading/glsl_compat.h"
#include "shading/proxy.h"

// BillboardData.info.x
#define MIRAGE_BILLBOARD_DIFFUSE 0     // a textured quad with alpha (colour layer)
#define MIRAGE_BILLBOARD_REFLECTIVE 1  // a reflector's quad with per-texel normal and position

// Storage bindings and texture units of the billboard method.
#define MIRAGE_BIND_BILLBOARDS 5          // SSBO BillboardData[]
#define MIRAGE_BIND_BILLBOARD_RANGES 6    // SSBO BillboardRange[] (one per reflector)
#define MIRAGE_BIND_BILLBOARD_ENTRIES 7   // SSBO int[]: billboard indices the ranges point into
#define MIRAGE_UNIT_BILLBOARD_COLOR 4     // sampler2DArray: diffuse colour, premultiplied alpha
#define MIRAGE_UNIT_BILLBOARD_NORMAL 5    // sampler2DArray: reflective normal (xyz) + alpha
#define MIRAGE_UNIT_BILLBOARD_POSITION 6  // sampler2DArray: reflective surface position
#define MIRAGE_UNIT_BILLBOARD_ENV 7  // samplerCube: the environment without billboarded objects

// Coverage at or above this counts as a hit (alpha test).
#define MIRAGE_BILLBOARD_ALPHA_CUTOFF 0.5f

SHARED_BEGIN

// One billboard: the quad corner + u * edge_u + v * edge_v, (u, v) in [0, 1]^2, with its texture
// (u, v) = (s, t) on layer info.y of the colour (diffuse) or normal/position (reflective) arrays.
struct BillboardData {
  vec4 corner;  // xyz: the corner at (u, v) = (0, 0)
  vec4 edge_u;  // xyz: the edge along u (perpendicular to edge_v)
  vec4 edge_v;  // xyz: the edge along v
  ivec4 info;   // x: MIRAGE_BILLBOARD_*; y: texture layer; z: the reflector a reflective
                // billboard stands for (0-based, -1 for diffuse); w: its material (-1)
};

// Per reflector (0-based), which list entries its rays test: x, y: first entry and count of
// diffuse billboards; z, w: first entry and count of reflective billboards (never its own).
struct BillboardRange {
  ivec4 range;
};

SHARED_FN float billboard_hit(BillboardData b, vec3 origin, vec3 dir, float t_min,
                              SHARED_OUT(vec2) uv) {
  return ray_quad(origin, dir, vec3(b.corner), vec3(b.edge_u), vec3(b.edge_v), t_min, uv);
}

// How (u, v) at the hit moves when the ray's origin moves by d_origin and its direction by
// d_dir (one pixel's ray differential): the footprint a mip-mapped lookup filters over.
SHARED_FN vec2 billboard_uv_differential(BillboardData b, vec3 dir, float t, vec3 d_origin,
                                         vec3 d_dir) {
  vec3 n = cross(vec3(b.edge_u), vec3(b.edge_v));
  vec3 dp = d_origin + t * d_dir;
  float dn = dot(dir, n);
  if (abs(dn) > 1.0e-20f) dp -= dir * (dot(dp, n) / dn);  // slide back onto the plane
  return vec2(dot(dp, vec3(b.edge_u)) / dot(vec3(b.edge_u), vec3(b.edge_u)),
              dot(dp, vec3(b.edge_v)) / dot(vec3(b.edge_v), vec3(b.edge_v)));
}

SHARED_END

#ifndef MIRAGE_GLSL
static_assert(sizeof(mirage::shading::BillboardData) == 4 * 16, "BillboardData layout");
static_assert(sizeof(mirage::shading::BillboardRange) == 16, "BillboardRange layout");
#endif

#endif  // MIRAGE_METHODS_BILLBOARD_BILLBOARD_SHARED_H
