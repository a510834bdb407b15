// The view-volume culling where a C3RC's swept triangle folds over itself (a concave reflector):
// the fold (caustic) surfaces bound the view volume too, besides the base, the side walls and
// the far cap, and a box they cross without touching those must still be kept. Boxes of 0.01,
// 0.1 and 1 times the base triangle's size are placed across points of the fold, and none that
// holds a projecting point may be culled — by the hull planes or by the exact test, the very
// code (c3rc_cull_shared.h) the GPU culling runs as GLSL.
#include <gtest/gtest.h>

#include <cstdio>

#include "methods/c3rc_cases.h"
#include "methods/hybrid/c3rc_cull.h"

namespace mirage::test {
namespace {

using namespace c3rc_cases;
namespace sh = shading;

// A point where the sweep (w, λ) ↦ Σ w_k (v_k + λ d_k) folds: its Jacobian n(λ)·d(w) =
// Σ w_k s_k(λ), s_k = n(λ)·d_k, vanishes with w inside the simplex. At a λ where one ray's s_k
// has the other sign from the other two, those w form the segment between the edge points where
// the two-term sum vanishes; a random point of it. False when no λ tried has mixed signs.
bool randomFoldPoint(const C3rcData& c, Rng& rng, vec3& fold) {
  const vec3 v[3] = {vec3(c.v0), vec3(c.v1), vec3(c.v2)};
  const vec3 d[3] = {vec3(c.d0), vec3(c.d1), vec3(c.d2)};
  const float lo = c.info.x, hi = std::min(c.info.y, c.info.w);
  for (int attempt = 0; attempt < 64; ++attempt) {
    const float lambda = uniformIn(rng, lo, hi);
    const vec3 n = sh::c3rc_normal(c, lambda);
    const float s[3] = {glm::dot(n, d[0]), glm::dot(n, d[1]), glm::dot(n, d[2])};
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      if (!((s[i] > 0.0f && s[j] < 0.0f && s[k] < 0.0f) ||
            (s[i] < 0.0f && s[j] > 0.0f && s[k] > 0.0f)))
        continue;
      // On edge i-j the weight t of j with (1 − t) s_i + t s_j = 0; the same on edge i-k.
      const float tj = s[i] / (s[i] - s[j]), tk = s[i] / (s[i] - s[k]);
      const float u = uniformIn(rng, 0.0f, 1.0f);
      float w[3];
      w[j] = u * tj;
      w[k] = (1.0f - u) * tk;
      w[i] = 1.0f - w[j] - w[k];
      fold = vec3(0.0f);
      for (int m = 0; m < 3; ++m) fold += w[m] * (v[m] + lambda * d[m]);
      return true;
    }
  }
  return false;
}

// A box of about `size` (each side 0.5 to 1.5 times it) with `p` at a random place inside.
Bounds3 boxAcross(const vec3& p, float size, Rng& rng) {
  const vec3 side(size * uniformIn(rng, 0.5f, 1.5f), size * uniformIn(rng, 0.5f, 1.5f),
                  size * uniformIn(rng, 0.5f, 1.5f));
  const vec3 lo = p - side * vec3(uniformIn(rng, 0.0f, 1.0f), uniformIn(rng, 0.0f, 1.0f),
                                  uniformIn(rng, 0.0f, 1.0f));
  return {lo, lo + side};
}

// Some point of the box (a 6 x 6 x 6 grid over it, and `extra`) projects (no slack: a point the
// splatting pass would splat).
bool holdsProjectingPoint(const C3rcData& c, const Bounds3& box, const vec3& extra) {
  vec4 p0, p1, p2;
  if (sh::c3rc_project(c, extra, 0.0f, true, p0, p1, p2) > 0) return true;
  constexpr int kGrid = 5;
  for (int x = 0; x <= kGrid; ++x)
    for (int y = 0; y <= kGrid; ++y)
      for (int z = 0; z <= kGrid; ++z) {
        const vec3 t = vec3(float(x), float(y), float(z)) / float(kGrid);
        if (sh::c3rc_project(c, glm::mix(box.lo, box.hi, t), 0.0f, true, p0, p1, p2) > 0)
          return true;
      }
  return false;
}

TEST(HybridFoldCulling, NeverCullsABoxAcrossAFoldHoldingAProjectingPoint) {
  Rng rng(24);
  const float scales[3] = {0.01f, 0.1f, 1.0f};
  int holding[3] = {0, 0, 0}, culled_exact[3] = {0, 0, 0}, culled_hull[3] = {0, 0, 0};
  int folding = 0;
  for (int trial = 0; folding < 400 && trial < 20000; ++trial) {
    const Triangle t = randomTriangle(rng);
    const Family family = trial % 4 == 3 ? kRandomRays : kConvergent;
    const C3rcData c = cameraOf(t, familyRays(family, t, rng).d);
    if ((int(c.info.z) & MIRAGE_C3RC_MULTIPLE) == 0) continue;
    ++folding;
    for (int b = 0; b < 6; ++b) {
      vec3 fold;
      if (!randomFoldPoint(c, rng, fold)) break;
      for (int s = 0; s < 3; ++s) {
        const Bounds3 box = boxAcross(fold, scales[s] * t.longest(), rng);
        if (!holdsProjectingPoint(c, box, fold)) continue;
        ++holding[s];
        const bool hull = hullRejects(c, box), exact = hull || !boxMeetsViewVolume(c, box);
        culled_hull[s] += hull ? 1 : 0;
        culled_exact[s] += exact ? 1 : 0;
        EXPECT_FALSE(exact) << "scale " << scales[s] << ", trial " << trial << ", box " << b;
      }
    }
  }
  for (int s = 0; s < 3; ++s)
    std::printf(
        "boxes of %.2fx the triangle across a fold: %d hold a projecting point, %d of "
        "them culled (%.2f %%; hull planes %d)\n",
        scales[s], holding[s], culled_exact[s],
        holding[s] ? 100.0 * culled_exact[s] / holding[s] : 0.0, culled_hull[s]);
  EXPECT_EQ(folding, 400) << "enough folding C3RCs";
  for (int s = 0; s < 3; ++s) {
    EXPECT_GT(holding[s], 1000) << "scale " << scales[s];
    EXPECT_EQ(culled_hull[s], 0) << "scale " << scales[s];
  }
}

}  // namespace
}  // namespace mirage::test
