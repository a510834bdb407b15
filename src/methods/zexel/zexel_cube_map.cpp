#include "methods/zexel/zexel_cube_map.h"

#include <algorithm>
#include <cmath>

#include "shading/cubemap.h"

// The shared search reads the map through this accessor; the map is the calling thread's.
namespace mirage::shading {
namespace {
thread_local const ZexelCubeMap* g_searched = nullptr;
}
inline float zexel_cube_distance(int, vec3 direction) {
  return g_searched->sample(direction).w;
}
}  // namespace mirage::shading

#include "methods/zexel/zexel_inverse_shared.h"

static_assert(mirage::kZexelInverseSky == ZEXEL_INVERSE_SKY &&
              mirage::kZexelInverseHit == ZEXEL_INVERSE_HIT &&
              mirage::kZexelInverseExposed == ZEXEL_INVERSE_EXPOSED);

namespace mirage {

vec4 ZexelCubeMap::sample(const vec3& d) const {
  vec2 st;
  const int face = shading::cube_face_st(d, st);
  const float x = st.x * float(size) - 0.5f, y = st.y * float(size) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  // Taps outside the face come from the neighbouring face, as GL's seamless filtering does.
  auto tap = [&](int xi, int yi) {
    if (xi >= 0 && yi >= 0 && xi < size && yi < size) return texel(face, xi, yi);
    const vec2 outside((float(xi) + 0.5f) / float(size), (float(yi) + 0.5f) / float(size));
    vec2 st2;
    const int f2 = shading::cube_face_st(shading::cube_direction(face, outside), st2);
    return texel(f2, std::clamp(int(st2.x * float(size)), 0, size - 1),
                 std::clamp(int(st2.y * float(size)), 0, size - 1));
  };
  // Weights of zero leave a sky texel's 1e30 out exactly, as the GPU's float filtering does.
  auto mix = [](const vec4& a, const vec4& b, float w) {
    return w <= 0.0f ? a : (w >= 1.0f ? b : a * (1.0f - w) + b * w);
  };
  return mix(mix(tap(x0, y0), tap(x0 + 1, y0), fx), mix(tap(x0, y0 + 1), tap(x0 + 1, y0 + 1), fx),
             fy);
}

vec3 ZexelCubeMap::texelDirection(int face, int x, int y) const {
  const vec2 st((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
  return glm::normalize(shading::cube_direction(face, st));
}

ZexelInverseSettings zexelInverseSettings(int face_size, float step_texels) {
  ZexelInverseSettings s;
  s.step_angle = step_texels * 0.5f * glm::pi<float>() / float(std::max(face_size, 1));
  s.max_steps = int(std::ceil(glm::pi<float>() / s.step_angle)) + 1;
  return s;
}

ZexelInverseHit zexelInverseWarp(const ZexelCubeMap& map, const vec3& origin, const vec3& dir,
                                 const ZexelInverseSettings& settings) {
  shading::g_searched = &map;
  ZexelInverseHit hit;
  hit.t = shading::zexel_inverse_warp(0, origin - map.centre, dir, settings.step_angle,
                                      settings.max_steps, settings.max_slope, hit.direction,
                                      hit.status, hit.samples);
  return hit;
}

}  // namespace mirage
