#include "gpu/texture.h"

#include <algorithm>
#include <bit>

#include "core/error.h"

namespace mirage::gpu {

namespace {
void checkSize(int width, int height, int layers) {
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throwInput("texture size {}x{} is outside the driver's range 1..{}", width, height, max_size);
  if (layers < 1 || layers > max_layers)
    throwInput("texture layer count {} is outside the driver's range 1..{}", layers, max_layers);
}
}  // namespace

Texture::Texture(GLenum target, GLenum format, ivec2 size, int layers, int levels)
    : target_(target), format_(format), size_(size), layers_(layers), levels_(levels) {
  if (target == 0) return;  // a view: view() makes the name
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  handle_ = Handle<TextureTraits>(id);
  setDefaultSampling();
}

void Texture::setDefaultSampling() {
  setFilter(levels_ > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
  setWrap(GL_CLAMP_TO_EDGE);
}

Texture Texture::view(const Texture& source, GLenum target, int first_layer, int layers) {
  if (first_layer < 0 || layers < 1 || first_layer + layers > source.layers_ ||
      (target == GL_TEXTURE_2D && layers != 1))
    throwRuntime("texture view of layers {}..{} of a {}-layer texture", first_layer,
                 first_layer + layers - 1, source.layers_);
  Texture t(0, source.format_, source.size_, layers, source.levels_);
  t.target_ = target;
  // glTextureView needs a name that has never been bound: glGenTextures, not glCreateTextures.
  GLuint id = 0;
  glGenTextures(1, &id);
  glTextureView(id, target, source.id(), source.format_, 0, GLuint(source.levels_),
                GLuint(first_layer), GLuint(layers));
  t.handle_ = Handle<TextureTraits>(id);
  t.setDefaultSampling();
  return t;
}

int Texture::fullMipLevels(int size) {
  return std::bit_width(unsigned(std::max(size, 1)));
}

Texture Texture::create2D(GLenum internal_format, int width, int height, int levels) {
  checkSize(width, height, 1);
  Texture t(GL_TEXTURE_2D, internal_format, {width, height}, 1, levels);
  glTextureStorage2D(t.id(), levels, internal_format, width, height);
  return t;
}

Texture Texture::create2DArray(GLenum internal_format, int width, int height, int layers,
                               int levels) {
  checkSize(width, height, layers);
  Texture t(GL_TEXTURE_2D_ARRAY, internal_format, {width, height}, layers, levels);
  glTextureStorage3D(t.id(), levels, internal_format, width, height, layers);
  return t;
}

Texture Texture::createCube(GLenum internal_format, int size, int levels) {
  checkSize(size, size, 1);
  Texture t(GL_TEXTURE_CUBE_MAP, internal_format, {size, size}, 6, levels);
  glTextureStorage2D(t.id(), levels, internal_format, size, size);
  return t;
}

Texture Texture::createCubeArray(GLenum internal_format, int size, int cubes, int levels) {
  checkSize(size, size, 6 * cubes);
  Texture t(GL_TEXTURE_CUBE_MAP_ARRAY, internal_format, {size, size}, 6 * cubes, levels);
  glTextureStorage3D(t.id(), levels, internal_format, size, size, 6 * cubes);
  return t;
}

void Texture::upload(int level, GLenum format, GLenum type, const void* pixels) {
  int w = std::max(1, size_.x >> level), h = std::max(1, size_.y >> level);
  glTextureSubImage2D(id(), level, 0, 0, w, h, format, type, pixels);
}

void Texture::uploadLayer(int level, int layer, GLenum format, GLenum type, const void* pixels) {
  int w = std::max(1, size_.x >> level), h = std::max(1, size_.y >> level);
  glTextureSubImage3D(id(), level, 0, 0, layer, w, h, 1, format, type, pixels);
}

void Texture::uploadLayers(int level, int first_layer, int count, GLenum format, GLenum type,
                           const void* pixels) {
  int w = std::max(1, size_.x >> level), h = std::max(1, size_.y >> level);
  glTextureSubImage3D(id(), level, 0, 0, first_layer, w, h, count, format, type, pixels);
}

void Texture::downloadLayer(int level, int layer, GLenum format, GLenum type, void* out,
                            size_t bytes) const {
  int w = std::max(1, size_.x >> level), h = std::max(1, size_.y >> level);
  glGetTextureSubImage(id(), level, 0, 0, layer, w, h, 1, format, type, GLsizei(bytes), out);
}

void Texture::generateMipmaps() {
  glGenerateTextureMipmap(id());
}

void Texture::setFilter(GLenum min_filter, GLenum mag_filter) {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(min_filter));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(mag_filter));
}

void Texture::setWrap(GLenum wrap) {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GLint(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GLint(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_R, GLint(wrap));
}

}  // namespace mirage::gpu
