#include "methods/ssr/hiz_pyramid.h"

#include <algorithm>
#include <bit>

#include "methods/ssr/ssr_shared.h"

namespace mirage {

HiZPyramid::HiZPyramid() : program_(gpu::Program::compute("methods/ssr/hiz_build.comp")) {}

ivec2 HiZPyramid::paddedSize(ivec2 screen) {
  return ivec2(int(std::bit_ceil(unsigned(std::max(screen.x, 1)))),
               int(std::bit_ceil(unsigned(std::max(screen.y, 1)))));
}

ivec2 HiZPyramid::levelSize(ivec2 screen, int level) {
  return glm::max(paddedSize(screen) >> level, ivec2(1));
}

ivec2 HiZPyramid::coveredSize(ivec2 screen, int level) {
  const ivec2 cell(1 << level);
  return glm::max((screen + cell - 1) / cell, ivec2(1));
}

void HiZPyramid::build(const gpu::Texture& depth, ivec2 screen, const HiZDepthRange& range) {
  const ivec2 padded = paddedSize(screen);
  const int levels = gpu::Texture::fullMipLevels(std::max(padded.x, padded.y));
  if (screen != screen_ || texture_.id() == 0) {
    texture_ = gpu::Texture::create2D(GL_RG32F, padded.x, padded.y, levels);
    texture_.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
    screen_ = screen;
  }
  program_.use();
  program_.set("u_thickness", range.thickness);
  program_.set("u_near", range.near_plane);
  program_.set("u_far", range.far_plane);
  depth.bind(MIRAGE_UNIT_SSR_DEPTH);
  ivec2 below = screen;
  for (int level = 0; level < levels; ++level) {
    // Only the cells over the screen: a march clipped to the screen reads no other.
    const ivec2 size = coveredSize(screen, level);
    program_.set("u_out_size", size);
    program_.set("u_in_size", below);
    program_.set("u_copy", level == 0 ? 1 : 0);
    if (level > 0)
      glBindImageTexture(MIRAGE_IMAGE_SSR_LEVEL_IN, texture_.id(), level - 1, GL_FALSE, 0,
                         GL_READ_ONLY, GL_RG32F);
    glBindImageTexture(MIRAGE_IMAGE_SSR_LEVEL_OUT, texture_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RG32F);
    glDispatchCompute(GLuint((size.x + MIRAGE_SSR_GROUP - 1) / MIRAGE_SSR_GROUP),
                      GLuint((size.y + MIRAGE_SSR_GROUP - 1) / MIRAGE_SSR_GROUP), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    below = size;
  }
}

}  // namespace mirage
