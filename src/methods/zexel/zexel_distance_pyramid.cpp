#include "methods/zexel/zexel_distance_pyramid.h"

#include <string>

#include "methods/zexel/zexel_bounds_shared.h"
#include "methods/zexel/zexel_shared.h"

namespace mirage {

namespace {

gpu::Program buildStep(int step) {
  return gpu::Program::compute("methods/zexel/zexel_distance_pyramid.comp",
                               {"ZEXEL_PYRAMID_STEP " + std::to_string(step)});
}

void bindLevel(GLuint image, const gpu::Texture& texture, int level, GLenum access) {
  glBindImageTexture(image, texture.id(), level, GL_TRUE, 0, access, texture.internalFormat());
}

// One invocation a texel of every face of every cube at a level `width` texels across.
void dispatch(int width, int layers) {
  glDispatchCompute(GLuint((width + 7) / 8), GLuint((width + 7) / 8), GLuint(layers));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace

ZexelDistancePyramid::ZexelDistancePyramid()
    : copy_(buildStep(0)), reduce_(buildStep(1)), bound_(buildStep(2)), farthest_(buildStep(3)) {}

void ZexelDistancePyramid::build(const gpu::Texture& cubes) {
  const int size = cubes.size().x, layers = cubes.layers();
  top_level_ = shading::zexel_bound_top_level(size);
  if (pyramid_.size().x != size || pyramid_.layers() != layers) {
    pyramid_ = gpu::Texture::createCubeArray(GL_R32F, size, layers / 6, top_level_ + 1);
    pyramid_.setFilter(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
    reduced_ = gpu::Texture::createCubeArray(GL_RG32F, size, layers / 6, top_level_ + 1);
    reduced_.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
    far_ = gpu::Buffer(size_t(layers / 6) * sizeof(float));
  }
  copy_.use();
  copy_.set("u_width", size);
  glBindImageTexture(MIRAGE_IMAGE_ZEXEL_LEVEL_IN, cubes.id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                     GL_RGBA32F);
  bindLevel(MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, pyramid_, 0, GL_WRITE_ONLY);
  bindLevel(MIRAGE_IMAGE_ZEXEL_REDUCED, reduced_, 0, GL_WRITE_ONLY);
  dispatch(size, layers);
  reduce_.use();
  for (int level = 1; level <= top_level_; ++level) {
    reduce_.set("u_width", size >> level);
    bindLevel(MIRAGE_IMAGE_ZEXEL_LEVEL_IN, reduced_, level - 1, GL_READ_ONLY);
    bindLevel(MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, reduced_, level, GL_WRITE_ONLY);
    dispatch(size >> level, layers);
  }
  bound_.use();
  reduced_.bind(MIRAGE_UNIT_ZEXEL_REDUCED);
  for (int level = ZEXEL_BOUND_FIRST_LEVEL; level <= top_level_; ++level) {
    bound_.set("u_width", size >> level);
    bound_.set("u_level", level);
    bindLevel(MIRAGE_IMAGE_ZEXEL_LEVEL_OUT, pyramid_, level, GL_WRITE_ONLY);
    dispatch(size >> level, layers);
  }
  farthest_.use();
  farthest_.set("u_width", size >> top_level_);
  farthest_.set("u_cubes", layers / 6);
  bindLevel(MIRAGE_IMAGE_ZEXEL_LEVEL_IN, reduced_, top_level_, GL_READ_ONLY);
  far_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_FAR);
  glDispatchCompute(GLuint((layers / 6 + 7) / 8), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void ZexelDistancePyramid::bind() const {
  pyramid_.bind(MIRAGE_UNIT_ZEXEL_DISTANCES);
  far_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_ZEXEL_FAR);
}

}  // namespace mirage
