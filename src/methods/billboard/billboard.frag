// Method `billboard`: the reflected scene replaced by billboards (the impostor paper, §3.1, and
// the order-K pixel algorithm of its slides). For reflection order K, at each bounce the ray
// tests the diffuse billboards built for the reflector it leaves and, unless it is the last
// bounce, the reflective billboards of the other reflectors; the nearest alpha-tested hit wins:
// a diffuse billboard gives its texel, a reflective one reflects the ray about its texel's normal
// from its texel's surface point, and a miss gives the environment (without the billboarded
// objects). Cost O(K (D + R)) per pixel; the billboards live in storage buffers, so any number
// renders.
#include "render/shaders/reflector.glsl"
#include "methods/billboard/billboard_shared.h"

layout(std430, binding = MIRAGE_BIND_BILLBOARDS) readonly buffer BillboardBlock {
  BillboardData billboards[];
};
layout(std430, binding = MIRAGE_BIND_BILLBOARD_RANGES) readonly buffer RangeBlock {
  BillboardRange billboard_ranges[];
};
layout(std430, binding = MIRAGE_BIND_BILLBOARD_ENTRIES) readonly buffer EntryBlock {
  int billboard_entries[];
};
layout(binding = MIRAGE_UNIT_BILLBOARD_COLOR) uniform sampler2DArray u_billboard_color;
layout(binding = MIRAGE_UNIT_BILLBOARD_NORMAL) uniform sampler2DArray u_billboard_normal;
layout(binding = MIRAGE_UNIT_BILLBOARD_POSITION) uniform sampler2DArray u_billboard_position;
layout(binding = MIRAGE_UNIT_BILLBOARD_ENV) uniform samplerCube u_billboard_env;
uniform int u_captured_env;  // 1: misses read u_billboard_env (objects without billboards)
// The billboard-to-environment morph (§3.2; u_ground >= 0 when on): the ground billboard and its
// transition walls form the box [u_morph_min, u_morph_max]; E = u_morph_centre.
uniform int u_ground = -1;
uniform vec3 u_morph_min;
uniform vec3 u_morph_max;
uniform vec3 u_morph_centre;

BillboardData billboard_data(int index) { return billboards[index]; }
int billboard_list_entry(int position) { return billboard_entries[position]; }
float billboard_coverage(BillboardData b, vec2 uv) {
  vec3 coords = vec3(uv, float(b.info.y));
  return b.info.x == MIRAGE_BILLBOARD_DIFFUSE ? textureLod(u_billboard_color, coords, 0.0f).a
                                              : textureLod(u_billboard_normal, coords, 0.0f).a;
}

#include "methods/billboard/billboard_nearest_shared.h"

#define MAX_BOUNCES 16

// What the environment shows along `dir`, filtered by the ray's footprint.
vec3 miss_radiance(vec3 dir, vec3 d_dir_x, vec3 d_dir_y) {
  bool mip = frame.options.y != 0;
  if (u_captured_env != 0)
    return mip ? textureGrad(u_billboard_env, dir, d_dir_x, d_dir_y).rgb
               : textureLod(u_billboard_env, dir, 0.0f).rgb;
  return mip ? textureGrad(u_environment, dir, d_dir_x, d_dir_y).rgb
             : textureLod(u_environment, dir, 0.0f).rgb;
}

// A diffuse billboard's texel at uv, filtered over the footprint (duv_x, duv_y); the colour is
// premultiplied by coverage, so dividing by alpha averages the covered texels only.
vec3 diffuse_texel(BillboardData b, vec2 uv, vec2 duv_x, vec2 duv_y) {
  vec3 coords = vec3(uv, float(b.info.y));
  vec4 c = frame.options.y != 0 ? textureGrad(u_billboard_color, coords, duv_x, duv_y)
                                 : textureLod(u_billboard_color, coords, 0.0f);
  return c.rgb / max(c.a, 1.0e-4f);
}

vec4 reflected_radiance(vec3 position, vec3 direction, vec3 normal, int reflector) {
  int from = reflector - 1;
  vec3 origin = position, dir = direction;
  // The ray differential: one pixel's change of origin and direction.
  vec3 dox = g_dPdx, doy = g_dPdy, ddx = g_dRdx, ddy = g_dRdy;
  // The reflective bounces, unwound at the end: each mixes its base colour with what it reflects.
  int stack_material[MAX_BOUNCES];
  float stack_cos[MAX_BOUNCES];
  float stack_distance[MAX_BOUNCES];
  int depth = 0;
  int order = min(frame.options.x, MAX_BOUNCES);
  float scene_scale = max(length(frame.eye.xyz - position), 1.0f);
  float t_min = 1.0e-4f * scene_scale;
  float first_distance = MISS_DISTANCE;
  vec3 radiance = vec3(0.0f);
  for (int bounce = 1; bounce <= order; ++bounce) {
    ivec4 range = billboard_ranges[from].range;
    float t = MISS_DISTANCE;
    vec2 uv = vec2(0.0f);
    int hit = nearest_billboard(origin, dir, range.x, range.y, t_min, t, uv);
    if (bounce < order) {
      int reflective = nearest_billboard(origin, dir, range.z, range.w, t_min, t, uv);
      if (reflective >= 0) hit = reflective;
    }
    // The ground box, if nearer than every billboard: the ground billboard, the morph on a
    // wall, the environment through the open top.
    int face = -1;
    float t_box = u_ground >= 0 ? ray_box_exit(origin, dir, u_morph_min, u_morph_max, face) : -1.0f;
    if (t_box >= 0.0f && t_box < t && face != MIRAGE_BOX_MAX_Y) {
      if (depth == 0) first_distance = t_box;
      else stack_distance[depth - 1] = t_box;
      if (face == MIRAGE_BOX_MIN_Y) {
        BillboardData g = billboards[u_ground];
        vec2 g_uv = vec2(0.0f);
        float t_g = billboard_hit(g, origin, dir, 0.0f, g_uv);
        vec2 duv_x = billboard_uv_differential(g, dir, t_g, dox, ddx);
        vec2 duv_y = billboard_uv_differential(g, dir, t_g, doy, ddy);
        radiance = diffuse_texel(g, clamp(g_uv, 0.0f, 1.0f), duv_x, duv_y);
      } else {
        vec3 a = origin + t_box * dir;
        vec3 m = morph_direction(a, u_morph_centre, dir, a.y - u_morph_min.y,
                                 u_morph_max.y - u_morph_min.y);
        radiance = miss_radiance(m, ddx, ddy);
      }
      break;
    }
    float distance = hit >= 0 ? t : MISS_DISTANCE;
    if (depth == 0) first_distance = distance;
    else stack_distance[depth - 1] = distance;
    if (hit < 0) {
      radiance = miss_radiance(dir, ddx, ddy);
      break;
    }
    BillboardData b = billboards[hit];
    if (b.info.x == MIRAGE_BILLBOARD_DIFFUSE) {
      vec2 duv_x = billboard_uv_differential(b, dir, t, dox, ddx);
      vec2 duv_y = billboard_uv_differential(b, dir, t, doy, ddy);
      radiance = diffuse_texel(b, uv, duv_x, duv_y);
      break;
    }
    // A reflective billboard: continue from its surface point, about its normal.
    vec3 coords = vec3(uv, float(b.info.y));
    vec3 n = normalize(textureLod(u_billboard_normal, coords, 0.0f).xyz);
    vec3 p = textureLod(u_billboard_position, coords, 0.0f).xyz;
    if (dot(n, dir) > 0.0f) n = -n;
    stack_material[depth] = b.info.w;
    stack_cos[depth] = max(dot(n, -dir), 0.0f);
    stack_distance[depth] = MISS_DISTANCE;
    ++depth;
    // The differential travels with the ray; a curved reflector spreads it further, which this
    // first-order transfer ignores (the lookup is then sharper than the ray tracer's average).
    dox += t * ddx;
    doy += t * ddy;
    origin = p + n * t_min;
    dir = reflect(dir, n);
    from = b.info.z;
  }
  for (int i = depth - 1; i >= 0; --i)
    radiance = shade_reflector(materials[stack_material[i]], stack_cos[i], stack_distance[i],
                               radiance);
  return vec4(radiance, first_distance);
}
