#include "methods/zexel/zexel_maps.h"

#include <algorithm>
#include <cmath>

#include "methods/zexel/zexel_camera.h"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"
#include "methods/zexel/zexel_warp_shared.h"
#include "shading/shading.h"

namespace mirage {

ZexelMirrorMaps::ZexelMirrorMaps(int mirror, const ZexelMapOptions& options)
    : mirror_(mirror), options_(options) {}

WarpCamera ZexelMirrorMaps::warpCamera(int map, int level) const {
  const View& v = view(map);
  // A level-l texel (u, v) covers level 0's 2^l x 2^l block centred at 2^l (u, v).
  const float scale = float(1 << level);
  mat3 p = zexelPixelMatrix(v, v.nearPlane());
  p[0] *= scale;
  p[1] *= scale;
  return {p, v.eye()};
}

void ZexelMirrorMaps::capture(FrameContext& frame, const vec3& point, const vec3& normal,
                              FrameTarget& scratch, const gpu::Program& base,
                              const gpu::Program& pyramid) {
  const Bounds3 b = frame.gpu.instanceBounds(mirror_);
  point_ = point;
  normal_ = normal;
  half_diagonal_ = std::max(0.5f * glm::length(b.extent()), 1e-4f);
  const mat3 axes = zexelMirrorFrame(normal);
  directions_.clear();
  views_.clear();
  for (const vec3& w : zexelHemisphere(options_.count, options_.cone)) {
    directions_.push_back(axes * w);
    views_.push_back(zexelHemisphereView(point, normal, directions_.back(), half_diagonal_,
                                         options_.size, options_.fov));
  }
  const int levels = gpu::Texture::fullMipLevels(options_.size);
  if (maps_.id() == 0 || maps_.layers() != count() || maps_.levels() != levels)
    maps_ = gpu::Texture::create2DArray(GL_RGBA32F, options_.size, options_.size, count(), levels);
  for (int m = 0; m < count(); ++m) {
    scratch.bind();
    scratch.clear();
    frame.passes.begin(views_[size_t(m)], frame.settings);
    frame.passes.drawDirect();
    frame.passes.drawReflectors(base, mirror_);
    glCopyImageSubData(scratch.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, maps_.id(),
                       GL_TEXTURE_2D_ARRAY, 0, 0, 0, m, options_.size, options_.size, 1);
  }
  // The hierarchy, one level from the one above.
  pyramid.use();
  for (int level = 1; level < levels; ++level) {
    const int width = this->width(level);
    glBindImageTexture(MIRAGE_IMAGE_ZEXEL_LEVEL_IN, maps_.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY,
                       GL_RGBA32F);
    glBindImageTexture(MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, maps_.id(), level, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    pyramid.set("u_width", width);
    glDispatchCompute(GLuint((width + 7) / 8), GLuint((width + 7) / 8), GLuint(count()));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
  readBack();
}

void ZexelMirrorMaps::readBack() {
  cpu_.assign(size_t(count()) * size_t(levels()), ZexelMap2D{});
  // The tiles' levels always (the warp plans on them); every level for the CPU warper.
  const int first = options_.cpu_copies ? 0 : std::min(shading::ZEXEL_TILE_SPAN, levels() - 1);
  for (int level = first; level < levels(); ++level) {
    const int width = this->width(level);
    std::vector<vec4> all(size_t(width) * size_t(width) * size_t(count()));
    glGetTextureImage(maps_.id(), level, GL_RGBA, GL_FLOAT, GLsizei(all.size() * sizeof(vec4)),
                      all.data());
    for (int m = 0; m < count(); ++m) {
      ZexelMap2D& map = cpu_[size_t(m) * size_t(levels()) + size_t(level)];
      map.width = map.height = width;
      map.sky = 0.5f * shading::MISS_DISTANCE;
      const size_t n = size_t(width) * size_t(width);
      map.texels.assign(all.begin() + std::ptrdiff_t(n * size_t(m)),
                        all.begin() + std::ptrdiff_t(n * size_t(m + 1)));
    }
  }
}

std::vector<int> ZexelMirrorMaps::select(const vec3& mirrored_eye, int count) const {
  return nearestZexelMaps(directions_, point_, mirrored_eye, count);
}

int ZexelMirrorMaps::levelFor(int map, const View& output, float spacing_goal) const {
  if (levels() <= 1) return 0;
  // The map's centre zexel sees the mirror's centre, half a diagonal away: its spacing there.
  const WarpCamera in = warpCamera(map, 0);
  const mat3 po_inverse = glm::inverse(zexelPixelMatrix(output, output.nearPlane()));
  const vec2 xi(0.5f * float(options_.size));
  const float delta = shading::zexel_disparity_from_distance(in.p, xi, half_diagonal_);
  const vec3 o = shading::zexel_warp(po_inverse, in.p, in.c, output.eye(), delta, xi);
  const vec3 r = shading::zexel_warp(po_inverse, in.p, in.c, output.eye(), delta, xi + vec2(1, 0));
  const vec3 u = shading::zexel_warp(po_inverse, in.p, in.c, output.eye(), delta, xi + vec2(0, 1));
  const float spacing = std::max(glm::length(vec2(r) - vec2(o)), glm::length(vec2(u) - vec2(o)));
  // The coarsest level whose zexels land at most `spacing_goal` pixels apart.
  if (!(spacing > 0.0f)) return 0;
  return std::clamp(int(std::floor(std::log2(spacing_goal / spacing))), 0, levels() - 1);
}

}  // namespace mirage
