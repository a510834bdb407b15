#include "methods/zexel/zexel_tiles.h"

#include <bit>

#include "methods/zexel/zexel_splat_shared.h"
#include "methods/zexel/zexel_warp_shared.h"

namespace mirage {

namespace {

// Where zexel `texel` of `map` (pixel matrix `p`) lands in `out`; w <= 0: outside the map, never
// written or behind the camera.
vec3 landing(const ZexelMap2D& map, const mat3& p, const vec3& c, const mat3& po_inverse,
             const vec3& co, ivec2 texel) {
  if (texel.x < 0 || texel.y < 0 || texel.x >= map.width || texel.y >= map.height)
    return vec3(0.0f, 0.0f, -1.0f);
  const vec4& z = map.texels[size_t(texel.y) * size_t(map.width) + size_t(texel.x)];
  if (!(z.w > 0.0f)) return vec3(0.0f, 0.0f, -1.0f);
  const vec2 xi = vec2(texel) + 0.5f;
  const float delta = z.w >= map.sky ? 0.0f : shading::zexel_disparity_from_distance(p, xi, z.w);
  return shading::zexel_warp(po_inverse, p, c, co, delta, xi);
}

}  // namespace

ZexelTilePlan planZexelTiles(const ZexelWarpSource& source, const WarpCamera& out,
                             const ZexelSplatOptions& options) {
  const int t = options.tile_level, span = 1 << t;
  const ZexelMap2D& coarse = source.levels[t];
  const int tiles = (source.width + span - 1) / span;
  const mat3 po_inverse = glm::inverse(out.p), p = shading::zexel_level_matrix(source.camera.p, t);
  const vec3 c = source.camera.c;
  const int largest = options.splat > 0 ? options.splat : kMaxAutoSplat * options.unit;
  const vec4 bounds = shading::zexel_splat_bounds(options.rect, largest);
  ZexelTilePlan plan;
  plan.tile_level = t;
  plan.finest = options.finest;
  plan.by_level.resize(size_t(t - options.finest + 1));
  auto add = [&](ivec2 tile, int level, float spacing) {
    plan.by_level[size_t(level - options.finest)].push_back(
        {uint32_t(tile.x) | (uint32_t(tile.y) << 16), std::bit_cast<uint32_t>(spacing)});
    const long n = 1L << (t - level);
    plan.zexels += n * n;
    plan.tiles += 1;
    plan.level_sum += level;
  };
  for (int y = 0; y < tiles; ++y)
    for (int x = 0; x < tiles; ++x) {
      const ivec2 tile(x, y);
      // A tile past the last zexel of level t (a side not divisible by 2^t): the finest level.
      if (x >= coarse.width || y >= coarse.height) {
        add(tile, options.finest, 0.5f * options.goal);
        continue;
      }
      const float nearest = coarse.texels[size_t(y) * size_t(coarse.width) + size_t(x)].w;
      if (!(nearest > 0.0f)) continue;  // nothing of it was written
      if (!shading::zexel_tile_visible(po_inverse, source.camera.p, c, out.c,
                                       vec2(tile) * float(span), vec2(tile + 1) * float(span),
                                       nearest, bounds))
        continue;  // none of it can land on the mirror's pixels
      const vec3 o = landing(coarse, p, c, po_inverse, out.c, tile);
      if (!(o.z > 0.0f)) {  // behind the output camera: nothing of it is seen near the mirror
        add(tile, t, options.goal);
        continue;
      }
      const vec4 gaps(
          shading::zexel_gap(o, landing(coarse, p, c, po_inverse, out.c, tile - ivec2(1, 0))),
          shading::zexel_gap(o, landing(coarse, p, c, po_inverse, out.c, tile + ivec2(1, 0))),
          shading::zexel_gap(o, landing(coarse, p, c, po_inverse, out.c, tile - ivec2(0, 1))),
          shading::zexel_gap(o, landing(coarse, p, c, po_inverse, out.c, tile + ivec2(0, 1))));
      const vec2 spacing = shading::zexel_spacing(gaps);
      const int level = options.lod
                            ? shading::zexel_tile_level(spacing.x, t, options.finest, options.goal)
                            : options.finest;
      add(tile, level, spacing.y / float(1 << (t - level)));
    }
  return plan;
}

}  // namespace mirage
