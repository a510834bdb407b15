#include "methods/zexel/zexel_cube_map.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"
#include "gpu/loop_budget.h"
#include "shading/cubemap.h"

// The shared search and the bounds' build read the map through these accessors; the map is the
// calling thread's.
namespace mirage::shading {
namespace {
thread_local const ZexelCubeMap* g_searched = nullptr;
thread_local const std::vector<ZexelCubeMap::Faces>* g_reduced = nullptr;  // M_L by level
}  // namespace
inline float zexel_cube_distance(int, vec3 direction, int level) {
  return level == 0 ? g_searched->sample(direction).w : g_searched->bound(level, direction);
}
// Nearest, as the build's sampler reads M_L.
inline float zexel_reduced_distance(int, vec3 direction, int level) {
  vec2 st;
  const int face = cube_face_st(direction, st);
  const int width = g_searched->size >> level;
  const int x = std::clamp(int(st.x * float(width)), 0, width - 1);
  const int y = std::clamp(int(st.y * float(width)), 0, width - 1);
  return (*g_reduced)[size_t(level)][size_t(face)][size_t(y) * size_t(width) + size_t(x)];
}
}  // namespace mirage::shading

#define ZEXEL_BOUNDS_BUILD
#include "methods/zexel/zexel_bounds_shared.h"
#include "methods/zexel/zexel_inverse_shared.h"

static_assert(mirage::kZexelInverseSky == ZEXEL_INVERSE_SKY &&
              mirage::kZexelInverseHit == ZEXEL_INVERSE_HIT &&
              mirage::kZexelInverseExposed == ZEXEL_INVERSE_EXPOSED);

namespace mirage {

namespace {

// Bilinear along `d` over faces `width` texels wide, seamless across faces as GL filters:
// `texel(face, x, y)` is a texel's value.
template <typename Texel>
auto bilinear(int width, const vec3& d, const Texel& texel) {
  vec2 st;
  const int face = shading::cube_face_st(d, st);
  const float x = st.x * float(width) - 0.5f, y = st.y * float(width) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  // Taps outside the face come from the neighbouring face, as GL's seamless filtering does.
  auto tap = [&](int xi, int yi) {
    if (xi >= 0 && yi >= 0 && xi < width && yi < width) return texel(face, xi, yi);
    const vec2 outside((float(xi) + 0.5f) / float(width), (float(yi) + 0.5f) / float(width));
    vec2 st2;
    const int f2 = shading::cube_face_st(shading::cube_direction(face, outside), st2);
    return texel(f2, std::clamp(int(st2.x * float(width)), 0, width - 1),
                 std::clamp(int(st2.y * float(width)), 0, width - 1));
  };
  // Weights of zero leave a sky texel's 1e30 out exactly, as the GPU's float filtering does.
  auto mix = [](const auto& a, const auto& b, float w) {
    return w <= 0.0f ? a : (w >= 1.0f ? b : a * (1.0f - w) + b * w);
  };
  return mix(mix(tap(x0, y0), tap(x0 + 1, y0), fx), mix(tap(x0, y0 + 1), tap(x0 + 1, y0 + 1), fx),
             fy);
}

}  // namespace

vec4 ZexelCubeMap::sample(const vec3& d) const {
  return bilinear(size, d, [&](int f, int x, int y) { return texel(f, x, y); });
}

float ZexelCubeMap::bound(int level, const vec3& d) const {
  const int width = size >> level;
  const std::vector<float>* faces_at = bounds[size_t(level)].data();
  return bilinear(width, d, [&](int f, int x, int y) {
    return faces_at[f][size_t(y) * size_t(width) + size_t(x)];
  });
}

void ZexelCubeMap::buildBounds() {
  const int top = shading::zexel_bound_top_level(size);
  std::vector<Faces> reduced(size_t(top) + 1);
  far = 0.0f;
  for (int f = 0; f < 6; ++f)
    for (const vec4& t : faces[size_t(f)]) {
      reduced[0][size_t(f)].push_back(t.w);
      if (t.w < shading::ZEXEL_SKY_DISTANCE) far = std::max(far, t.w);
    }
  for (int level = 1; level <= top; ++level) {
    const int width = size >> level, finer = width * 2;
    for (int f = 0; f < 6; ++f) {
      const std::vector<float>& in = reduced[size_t(level) - 1][size_t(f)];
      std::vector<float>& out = reduced[size_t(level)][size_t(f)];
      out.resize(size_t(width) * size_t(width));
      for (int y = 0; y < width; ++y)
        for (int x = 0; x < width; ++x) {
          auto at = [&](int i, int j) {
            return in[size_t(2 * y + j) * size_t(finer) + size_t(2 * x + i)];
          };
          out[size_t(y) * size_t(width) + size_t(x)] =
              std::min({at(0, 0), at(1, 0), at(0, 1), at(1, 1)});
        }
    }
  }
  shading::g_searched = this;
  shading::g_reduced = &reduced;
  bounds.assign(size_t(top) + 1, Faces{});
  for (int level = ZEXEL_BOUND_FIRST_LEVEL; level <= top; ++level) {
    const int width = size >> level;
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < width; ++y)
        for (int x = 0; x < width; ++x)
          bounds[size_t(level)][size_t(f)].push_back(
              shading::zexel_bound_texel(0, f, ivec2(x, y), level, width));
  }
}

vec3 ZexelCubeMap::texelDirection(int face, int x, int y) const {
  const vec2 st((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
  return glm::normalize(shading::cube_direction(face, st));
}

ZexelInverseSettings zexelInverseSettings(int face_size, float step_texels, bool bounds) {
  ZexelInverseSettings s;
  s.texel_angle = 0.5f * glm::pi<float>() / float(std::max(face_size, 1));
  s.top_level = bounds ? shading::zexel_bound_top_level(face_size) : 0;
  s.step_angle = step_texels * s.texel_angle;
  s.max_steps = int(std::ceil(glm::pi<float>() / s.step_angle)) + 1;
  return s;
}

long long zexelInverseLoopCost(const ZexelInverseSettings& settings) {
  const long long iterations =
      (settings.max_steps + 1LL) * (ZEXEL_INVERSE_BISECTIONS + 2LL);
  return gpu::loopCost(settings.top_level + 1) + gpu::loopCost(iterations);
}

ZexelInverseHit zexelInverseWarp(const ZexelCubeMap& map, const vec3& origin, const vec3& dir,
                                 const ZexelInverseSettings& settings) {
  shading::g_searched = &map;
  ZexelInverseHit hit;
  MIRAGE_CHECK(settings.top_level == 0 || int(map.bounds.size()) > settings.top_level);
  hit.t = shading::zexel_inverse_warp(
      0, origin - map.centre, dir, settings.step_angle, settings.max_steps, settings.max_slope,
      settings.texel_angle, settings.top_level, map.far, hit.direction, hit.status, hit.samples);
  return hit;
}

}  // namespace mirage
