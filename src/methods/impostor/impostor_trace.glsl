// The impostor paper's pixel algorithm for reflection order K, shared by the impostor methods'
// reflector shaders: at each bounce the ray tests the diffuse billboards built for the reflector
// it leaves and the reflective billboards of the other reflectors (on the last bounce only with
// u_last_bounce_reflective), and whatever other impostors the includer adds; the nearest
// alpha-tested hit wins: a diffuse billboard gives its texel, a reflective one reflects the ray
// about its texel's normal from its texel's surface point (or, with no bounce left, gives that
// reflector's base colour), and a miss gives the environment (without the impostored objects).
//
// The includer includes impostor_counts.glsl (the work counted) and defines, before including
// this file, the other impostors' hooks:
//   // The nearest hit of its impostors along the ray with t_min < t < t_best, for rays leaving
//   // reflector `from` (0-based): lowers t_best, sets `end` (what the path's end looks up) and
//   // returns true; false leaves both. dox..ddy: the ray differential, for the footprint.
//   // `reflective`: whether reflecting impostors may be hit (as for reflective billboards).
//   bool impostor_extra_hit(vec3 origin, vec3 dir, int from, bool reflective, float t_min,
//                           inout float t_best, vec3 dox, vec3 doy, vec3 ddx, vec3 ddy,
//                           out vec4 end);
//   // Whether the end found is a reflecting surface; if so its world normal there, its material
//   // and the reflector (0-based) the reflected ray leaves.
//   bool impostor_extra_reflects(vec4 end, out vec3 normal, out int material, out int leaves);
//   // The radiance at a path's end that impostor_extra_hit found (not a reflecting one).
//   vec3 impostor_extra_radiance(vec4 end);
#include "render/shaders/reflector.glsl"
#include "methods/impostor/billboard_shared.h"

layout(std430, binding = MIRAGE_BIND_BILLBOARDS) readonly buffer BillboardBlock {
  BillboardData billboards[];
};
layout(std430, binding = MIRAGE_BIND_BILLBOARD_CARRY) readonly buffer CarryBlock {
  BillboardCarry billboard_carries[];
};
layout(std430, binding = MIRAGE_BIND_BILLBOARD_RANGES) readonly buffer RangeBlock {
  BillboardRange billboard_ranges[];
};
layout(std430, binding = MIRAGE_BIND_BILLBOARD_ENTRIES) readonly buffer EntryBlock {
  int billboard_entries[];
};
layout(binding = MIRAGE_UNIT_BILLBOARD_SURFACE) uniform sampler2DArray u_billboard_surface;
layout(binding = MIRAGE_UNIT_BILLBOARD_POSITION) uniform sampler2DArray u_billboard_position;
layout(binding = MIRAGE_UNIT_BILLBOARD_ENV) uniform samplerCube u_billboard_env;
// The billboard-to-environment morph (§3.2; compiled in with IMPOSTOR_MORPH, the stage's define
// for --morph-height > 0; u_ground >= 0 when on): the ground billboard and its transition walls
// form the box [u_morph_min, u_morph_max]; E = u_morph_centre.
uniform int u_ground = -1;
uniform vec3 u_morph_min;
uniform vec3 u_morph_max;
uniform vec3 u_morph_centre;
// 1: the last bounce also tests reflective billboards, and a hit ends the path with that
// reflector's base colour (what the ray tracer shows at order K); 0: the paper's count, the
// last bounce tests diffuse billboards only.
uniform int u_last_bounce_reflective = 1;

BillboardData billboard_data(int index) { return billboards[index]; }
int billboard_list_entry(int position) { return billboard_entries[position]; }
// The nearest texel's coverage: the alpha test needs no filtering, and a fetch is a fraction of
// a filtered lookup's cost on llvmpipe.
float billboard_coverage(BillboardData b, vec2 uv) {
  ivec2 size = textureSize(u_billboard_surface, 0).xy;
  ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
  return texelFetch(u_billboard_surface, ivec3(texel, b.info.y), 0).a;
}

#include "methods/impostor/billboard_nearest_shared.h"

// The surface point a reflective billboard holds at uv, filtered over the covered texels only.
// The capture writes (point, 1) where the reflector covers a texel and leaves (0, 0, 0, 0)
// elsewhere, so a bilinear lookup at a silhouette returns (sum of w_i p_i, sum of w_i) over the
// covered texels: dividing by the filtered coverage averages their points. Undivided, the
// uncovered texels' zeros would pull the point towards the world origin. The carry moves the
// points along with the reflector's motion since its capture, rotation included.
vec3 billboard_surface_point(int index, BillboardData b, vec2 uv) {
  vec4 p = textureLod(u_billboard_position, vec3(uv, b.corner.w), 0.0f);
  return billboard_carry_point(billboard_carries[index], p.xyz / max(p.w, 1.0e-6f));
}

// Once the hit distance of the ray leaving a reflective billboard is known, that reflector's
// colour mix(base, tint * L, w) is settled into the running sum: it is linear in L, so no
// stack of bounces is needed.
void settle(int material, float cos_theta, float distance, inout vec3 sum, inout vec3 throughput) {
  MaterialData m = materials[material];
  float w = reflection_weight(m, cos_theta, distance);
  sum += throughput * vec3(m.albedo) * (1.0f - w);
  throughput *= vec3(m.tint) * w;
}

// What a bounce's ray meets first: a billboard (hit >= 0, at t, uv), another impostor (extra),
// or a wall or the floor of the ground box (box; the floor is handed over as the ground
// billboard), or nothing.
struct BounceHit {
  int hit;
  float t;
  vec2 uv;
  bool extra;
  vec4 extra_end;
  bool box;
  float t_box;
};

BounceHit nearest_bounce_hit(vec3 origin, vec3 dir, int from, bool reflective, float t_min,
                             vec3 dox, vec3 doy, vec3 ddx, vec3 ddy) {
  BounceHit h;
  // The list of the direction cell the ray leaves along; a planar reflector's, of the side
  // it leaves into.
  ivec4 range =
      billboard_list(billboard_ranges[billboard_list_index(from, dir, u_billboard_cells)], dir);
  h.t = MISS_DISTANCE;
  h.uv = vec2(0.0f);
  // The reflector's list holds its diffuse billboards, then the reflective ones right after
  // (range.z == range.x + range.y): one loop tests both.
  int tested = range.y + (reflective ? range.w : 0);
  g_impostor_candidates += tested;
  g_impostor_rays += 1;
  h.hit = nearest_billboard(origin, dir, range.x, tested, t_min, h.t, h.uv);
  h.extra_end = vec4(0.0f);
  h.extra = impostor_extra_hit(origin, dir, from, reflective, t_min, h.t, dox, doy, ddx, ddy,
                               h.extra_end);
  if (h.extra) h.hit = -1;
  // The ground box, if nearer than every billboard: the ground billboard through its floor,
  // the morph on a wall, the environment through the open top.
  int face = -1;
#ifdef IMPOSTOR_MORPH
  h.t_box = u_ground >= 0 ? ray_box_exit(origin, dir, u_morph_min, u_morph_max, face) : -1.0f;
#else
  // No morph (--morph-height 0): compiled out, since llvmpipe would pay for the box test.
  h.t_box = -1.0f;
#endif
  h.box = h.t_box >= 0.0f && h.t_box < h.t && face != MIRAGE_BOX_MAX_Y;
  if (h.box && face == MIRAGE_BOX_MIN_Y) {
    // The box's floor is the ground's plane: the quad's coordinates of the same point.
    h.hit = u_ground;
    h.extra = false;
    h.t = h.t_box;
    BillboardData g = billboards[h.hit];
    vec3 local = origin + h.t_box * dir - g.corner.xyz;
    h.uv = clamp(vec2(dot(local, g.edge_u.xyz) * g.edge_u.w, dot(local, g.edge_v.xyz) * g.edge_v.w),
                 0.0f, 1.0f);
    h.box = false;
  }
  if (h.box) h.extra = false;
  return h;
}

// Where a path ends: a billboard texel (layer >= 0, uv, footprint), another impostor (extra), a
// reflector's base colour (reflector >= 0), or the environment along env_dir.
struct PathEnd {
  float layer;
  int reflector;  // the material of a reflector hit on the last bounce
  vec2 uv, dx, dy;
  vec3 env_dir;
  bool extra;
  vec4 extra_end;
};

// A path that has met nothing yet: it ends in the environment along dir.
PathEnd environment_end(vec3 dir) {
  PathEnd e;
  e.layer = -1.0f;
  e.reflector = -1;
  e.uv = vec2(0.0f);
  e.dx = vec2(0.0f);
  e.dy = vec2(0.0f);
  e.env_dir = dir;
  e.extra = false;
  e.extra_end = vec4(0.0f);
  return e;
}

// The length of the bounce's path from origin to what it hit (MISS_DISTANCE for nothing). A
// reflective billboard stands in for its reflector: the path goes on from the surface point its
// texel holds (set here), not from the quad, so the path's length (the attenuation distance of
// the reflector the ray left) is measured to that point.
float bounce_distance(BounceHit h, vec3 origin, out vec3 surface_point) {
  BillboardData hit_board = billboards[max(h.hit, 0)];
  bool reflective_hit =
      !h.box && !h.extra && h.hit >= 0 && hit_board.info.x == MIRAGE_BILLBOARD_REFLECTIVE;
  surface_point = billboard_surface_point(max(h.hit, 0), hit_board, h.uv);
  return h.box ? h.t_box
               : (reflective_hit ? length(surface_point - origin)
                                 : (h.hit >= 0 || h.extra ? h.t : MISS_DISTANCE));
}

// The path's end, looked up once, at the level of the footprint (isotropic, as textureGrad on
// llvmpipe, at a fraction of its cost): a cube texel spans about (pi / 2) / size radians of
// direction, a billboard texel 1 / size of u and v. Without mip-mapping: level 0.
vec3 path_end_radiance(PathEnd e, vec3 ddx, vec3 ddy) {
  bool mip = frame.options.y != 0;
  float env_size = float(textureSize(u_billboard_env, 0).x);
  float env_footprint = max(length(ddx), length(ddy)) / length(e.env_dir) * env_size / 1.5707963f;
  float env_lod = mip ? log2(max(env_footprint, 1.0e-8f)) : 0.0f;
  vec3 env = textureLod(u_billboard_env, e.env_dir, env_lod).rgb;
  float surface_size = float(textureSize(u_billboard_surface, 0).x);
  float texel_footprint = max(length(e.dx), length(e.dy)) * surface_size;
  float texel_lod = mip ? log2(max(texel_footprint, 1.0e-8f)) : 0.0f;
  vec4 texel = textureLod(u_billboard_surface, vec3(e.uv, max(e.layer, 0.0f)), texel_lod);
  // Premultiplied by coverage: dividing by alpha averages the covered texels only.
  vec3 radiance = e.layer >= 0.0f ? texel.rgb / max(texel.a, 1.0e-4f) : env;
  if (e.extra) radiance = impostor_extra_radiance(e.extra_end);
  if (e.reflector >= 0) radiance = reflector_base(materials[e.reflector]);
  return radiance;
}

// Written for llvmpipe as much as for GPUs: llvmpipe runs both sides of every branch (masked),
// so the loop only finds hits and the path's end is looked up once, after it: one cube-map
// lookup and one billboard-texel lookup per pixel, whichever the path ended in.
vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  int from = reflector - 1;
  vec3 origin = position, dir = direction;
  // The ray differential: one pixel's change of origin and direction.
  vec3 dox = g_dPdx, doy = g_dPdy, ddx = g_dRdx, ddy = g_dRdy;
  int order = frame.options.x;
  float t_min = 1.0e-4f * max(length(frame.eye.xyz - position), 1.0f);
  float first_distance = MISS_DISTANCE;
  vec3 sum = vec3(0.0f), throughput = vec3(1.0f);
  int pending = -1;  // the material of the reflective billboard the ray last bounced off
  float pending_cos = 0.0f;
  PathEnd end = environment_end(dir);
  for (int bounce = 1; bounce <= order; ++bounce) {
    bool reflective = bounce < order || u_last_bounce_reflective != 0;
    BounceHit h = nearest_bounce_hit(origin, dir, from, reflective, t_min, dox, doy, ddx, ddy);
    float t = h.t;
    vec3 surface_point = vec3(0.0f);
    float distance = bounce_distance(h, origin, surface_point);
    if (pending >= 0) settle(pending, pending_cos, distance, sum, throughput);
    else first_distance = distance;
    end.env_dir = dir;
    if (h.box) {
      vec3 a = origin + h.t_box * dir;
      end.env_dir = morph_direction(a, u_morph_centre, dir, a.y - u_morph_min.y,
                                    u_morph_max.y - u_morph_min.y);
      break;
    }
    // A reflecting surface: its normal and point, the material and the reflector left next.
    vec3 n = vec3(0.0f), p = vec3(0.0f);
    int material = -1, leaves = -1;
    if (h.extra) {
      if (!impostor_extra_reflects(h.extra_end, n, material, leaves)) {
        end.extra_end = h.extra_end;
        end.extra = true;
        break;
      }
      p = origin + t * dir;
    } else {
      if (h.hit < 0) break;
      BillboardData b = billboards[h.hit];
      if (b.info.x == MIRAGE_BILLBOARD_DIFFUSE) {
        end.layer = float(b.info.y);
        end.uv = h.uv;
        end.dx = billboard_uv_differential(b, dir, t, dox, ddx);
        end.dy = billboard_uv_differential(b, dir, t, doy, ddy);
        break;
      }
      material = b.info.w;
      leaves = b.info.z;
      if (bounce < order) {
        vec3 stored = textureLod(u_billboard_surface, vec3(h.uv, float(b.info.y)), 0.0f).xyz;
        n = normalize(billboard_carry_normal(billboard_carries[h.hit], stored));
        p = surface_point;
      }
    }
    if (bounce == order) {
      end.reflector = material;  // no bounce left: the reflector's base colour
      break;
    }
    // Continue from the reflecting surface's point, about its normal.
    if (dot(n, dir) > 0.0f) n = -n;
    pending = material;
    pending_cos = max(dot(n, -dir), 0.0f);
    // The differential travels with the ray; a curved reflector spreads it further, which this
    // first-order transfer ignores (the lookup is then sharper than the ray tracer's average).
    dox += t * ddx;
    doy += t * ddy;
    origin = p + n * t_min;
    dir = reflect(dir, n);
    end.env_dir = dir;
    from = leaves;
  }
  impostor_count_pixel();
  return vec4(sum + throughput * path_end_radiance(end, ddx, ddy), first_distance);
}
