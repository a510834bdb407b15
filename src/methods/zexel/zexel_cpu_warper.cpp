#include "methods/zexel/zexel_cpu_warper.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "methods/zexel/zexel_warp_shared.h"
#include "shading/shading.h"

namespace mirage {

namespace {

// Where zexel (x, y) lands: (u, v, depth over the output plane distance); depth <= 0 when it
// was never written or lands behind the output camera. A zexel that saw nothing is a direction
// (δ = 0) and lands infinitely far.
vec3 landing(const ZexelMap2D& map, const mat3& po_inverse, const WarpCamera& in,
             const WarpCamera& out, int x, int y, float* delta_out = nullptr) {
  const vec4& t = map.texels[size_t(y) * size_t(map.width) + size_t(x)];
  if (!(t.w > 0.0f)) return vec3(0.0f, 0.0f, -1.0f);
  const vec2 xi(float(x) + 0.5f, float(y) + 0.5f);
  const float delta = t.w >= map.sky ? 0.0f : shading::zexel_disparity_from_distance(in.p, xi, t.w);
  if (delta_out) *delta_out = delta;
  return shading::zexel_warp(po_inverse, in.p, in.c, out.c, delta, xi);
}

// The splat side of a zexel: fixed, or (0) from the warp's magnification.
int splatSide(int splat, const mat3& po_inverse, const WarpCamera& in, const WarpCamera& out,
              float delta, int x, int y, vec2 landed, int unit = 1) {
  if (splat > 0) return splat;
  return shading::zexel_splat_side(po_inverse, in.p, in.c, out.c, delta,
                                   vec2(float(x) + 0.5f, float(y) + 0.5f), landed,
                                   kMaxAutoSplat * unit, unit);
}

// The s x s block of pixels whose centres are nearest (u, v), clipped to `rect` (within an image
// `rect_width` pixels wide).
template <typename Write>
void splatAt(vec2 uv, int splat, ivec4 rect, int rect_width, Write&& write) {
  const int x0 = int(std::floor(uv.x - 0.5f * float(splat - 1)));
  const int y0 = int(std::floor(uv.y - 0.5f * float(splat - 1)));
  for (int dy = 0; dy < splat; ++dy)
    for (int dx = 0; dx < splat; ++dx) {
      const int px = x0 + dx, py = y0 + dy;
      if (px >= rect.x && py >= rect.y && px < rect.z && py < rect.w)
        write(size_t(py) * size_t(rect_width) + size_t(px));
    }
}

// One sheet: columns [x_begin, x_end) and rows [y_begin, y_end) walked in the given directions.
struct Sheet {
  int x_from, x_to, x_step, y_from, y_to, y_step;  // inclusive from, exclusive to
  int x_lo, x_hi;                                  // its columns, ascending
  float p_lo, p_hi;  // the range of its zexels' pseudo-angle about the epipole (wedges.h)
};

// Zexels on one line through the epipole (an epipolar line) are the only ones that can land on
// one another, so a sheet also splits into wedges about the epipole that warp independently, each
// in the sheet's order: parallel work even where the epipole leaves a single sheet. A zexel's
// wedge is set by its pseudo-angle |p| = |dy| / (|dx| + |dy|) (dx, dy: its centre from the
// epipole), monotonic in the angle within a quadrant; per row, |p| >= q holds for the columns
// with |dx| <= |dy| (1 − q) / q, a run next to the epipole, so each wedge is a column interval.
struct Wedges {
  float ex, ey;
  int count;

  float pseudoAngle(float x, float y) const {
    const float dx = std::abs(x + 0.5f - ex), dy = std::abs(y + 0.5f - ey);
    return dy / std::max(dx + dy, 1e-30f);
  }
  // The first column past the run of columns of row `y` whose |p| is at least `q`, walking
  // away from the epipole: cut(q) for a sheet right of the epipole, where the run starts at x_lo.
  int cut(const Sheet& s, int y, float q, bool right) const {
    if (q <= 0.0f) return right ? s.x_hi : s.x_lo;
    const float dy = std::abs(float(y) + 0.5f - ey);
    const float t = std::min(dy * (1.0f - q) / q, 1e8f);
    if (right) return std::clamp(int(std::floor(ex - 0.5f + t)) + 1, s.x_lo, s.x_hi);
    return std::clamp(int(std::ceil(ex - 0.5f - t)), s.x_lo, s.x_hi);
  }
  // Wedge k's columns of row y: [first, last).
  std::array<int, 2> columns(const Sheet& s, int y, int k, bool right) const {
    auto boundary = [&](int j) {
      if (j <= 0) return -1.0f;     // every column
      if (j >= count) return 2.0f;  // none
      return s.p_lo + (s.p_hi - s.p_lo) * float(j) / float(count);
    };
    const int a = cut(s, y, boundary(k), right), b = cut(s, y, boundary(k + 1), right);
    return right ? std::array<int, 2>{b, a} : std::array<int, 2>{a, b};
  }
};

}  // namespace

std::vector<uint32_t> warpOcclusionCompatible(const ZexelMap2D& map, const WarpCamera& in,
                                              const WarpCamera& out, ivec2 size,
                                              const WarpOptions& options) {
  std::vector<std::atomic<uint32_t>> shown(size_t(size.x) * size_t(size.y));
  for (auto& s : shown) s.store(kNoZexel, std::memory_order_relaxed);
  const mat3 po_inverse = glm::inverse(out.p);
  const ivec4 clip(glm::max(ivec2(options.rect), ivec2(0)),
                   glm::min(ivec2(options.rect.z, options.rect.w), size));
  // The epipole: the output centre seen from the reference camera, homogeneous.
  const vec3 e = glm::inverse(in.p) * (out.c - in.c);
  const bool positive = e.z > 0.0f;
  const float big = 1e9f;
  const float ex = e.z != 0.0f ? std::clamp(e.x / e.z, -big, big) : (e.x >= 0.0f ? big : -big);
  const float ey = e.z != 0.0f ? std::clamp(e.y / e.z, -big, big) : (e.y >= 0.0f ? big : -big);
  // The column and row the epipole falls in, clamped to [0, size]: sheets are the quadrants.
  const int cx = int(std::clamp(std::floor(ex), 0.0f, float(map.width)));
  const int cy = int(std::clamp(std::floor(ey), 0.0f, float(map.height)));
  const Wedges wedges{ex, ey, std::max(options.wedges, 1)};
  // Toward the epipole (positive) or away from it (negative), per quadrant.
  auto walk = [&](int lo, int hi, bool below_epipole) {
    const bool ascending = positive == below_epipole;  // toward the epipole from below: up
    return ascending ? std::array<int, 3>{lo, hi, 1} : std::array<int, 3>{hi - 1, lo - 1, -1};
  };
  std::vector<Sheet> sheets;
  for (int qx = 0; qx < 2; ++qx)
    for (int qy = 0; qy < 2; ++qy) {
      const int x_lo = qx == 0 ? 0 : cx, x_hi = qx == 0 ? cx : map.width;
      const int y_lo = qy == 0 ? 0 : cy, y_hi = qy == 0 ? cy : map.height;
      if (x_lo >= x_hi || y_lo >= y_hi) continue;
      const auto wx = walk(x_lo, x_hi, qx == 0), wy = walk(y_lo, y_hi, qy == 0);
      Sheet sheet{wx[0], wx[1], wx[2], wy[0], wy[1], wy[2], x_lo, x_hi, 2.0f, -1.0f};
      for (int corner = 0; corner < 4; ++corner) {
        const float p = wedges.pseudoAngle(float((corner & 1) ? x_hi - 1 : x_lo),
                                           float((corner & 2) ? y_hi - 1 : y_lo));
        sheet.p_lo = std::min(sheet.p_lo, p);
        sheet.p_hi = std::max(sheet.p_hi, p);
      }
      sheets.push_back(sheet);
    }
  auto run = [&](const Sheet& s, int k) {
    const bool right = s.x_lo >= cx;  // the sheet's zexels lie right of the epipole
    for (int y = s.y_from; y != s.y_to; y += s.y_step) {
      const auto [first, last] = wedges.columns(s, y, k, right);
      if (first >= last) continue;
      const int from = s.x_step > 0 ? first : last - 1, to = s.x_step > 0 ? last : first - 1;
      for (int x = from; x != to; x += s.x_step) {
        float delta = 0.0f;
        const vec3 o = landing(map, po_inverse, in, out, x, y, &delta);
        if (!(o.z > 0.0f)) continue;
        const uint32_t index = uint32_t(y) * uint32_t(map.width) + uint32_t(x);
        const int side =
            splatSide(options.splat, po_inverse, in, out, delta, x, y, vec2(o), options.unit);
        splatAt(vec2(o), side, clip, size.x,
                [&](size_t pixel) { shown[pixel].store(index, std::memory_order_relaxed); });
      }
    }
  };
  const size_t tasks = sheets.size() * size_t(wedges.count);
  auto task = [&](size_t i) { run(sheets[i / size_t(wedges.count)], int(i) % wedges.count); };
  if (options.parallel)
    tbb::parallel_for(size_t(0), tasks, task);
  else
    for (size_t i = 0; i < tasks; ++i) task(i);
  std::vector<uint32_t> result(shown.size());
  for (size_t i = 0; i < shown.size(); ++i) result[i] = shown[i].load(std::memory_order_relaxed);
  return result;
}

std::vector<uint32_t> warpZBuffered(const ZexelMap2D& map, const WarpCamera& in,
                                    const WarpCamera& out, ivec2 size, int splat) {
  std::vector<uint32_t> shown(size_t(size.x) * size_t(size.y), kNoZexel);
  std::vector<float> depth(shown.size(), std::numeric_limits<float>::infinity());
  const mat3 po_inverse = glm::inverse(out.p);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      float delta = 0.0f;
      const vec3 o = landing(map, po_inverse, in, out, x, y, &delta);
      if (!(o.z > 0.0f)) continue;
      const uint32_t index = uint32_t(y) * uint32_t(map.width) + uint32_t(x);
      const int side = splatSide(splat, po_inverse, in, out, delta, x, y, vec2(o));
      splatAt(vec2(o), side, ivec4(0, 0, size), size.x, [&](size_t pixel) {
        if (o.z < depth[pixel]) {
          depth[pixel] = o.z;
          shown[pixel] = index;
        }
      });
    }
  return shown;
}

float zexelDistance(const ZexelMap2D& map, const WarpCamera& in, uint32_t index, const vec3& from) {
  const vec4& t = map.texels[index];
  if (t.w >= map.sky) return shading::MISS_DISTANCE;
  const vec2 xi(float(index % uint32_t(map.width)) + 0.5f,
                float(index / uint32_t(map.width)) + 0.5f);
  const vec3 ray = in.p * vec3(xi, 1.0f);
  return glm::length(in.c + glm::normalize(ray) * t.w - from);
}

}  // namespace mirage
