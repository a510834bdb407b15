#include "gpu/texture.h"

#include "gpu/framebuffer.h"

#include <algorithm>
#include <bit>

#include "core/error.h"
#include "gpu/memory.h"

namespace mirage::gpu {

namespace {

// The driver's limits, checked before anything is allocated: a method asking past them gets a
// GpuError naming the limit, and the frame renderer falls back to envmap.
void checkSize(GLenum target, int width, int height, int layers) {
  const bool cube = target == GL_TEXTURE_CUBE_MAP || target == GL_TEXTURE_CUBE_MAP_ARRAY;
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(cube ? GL_MAX_CUBE_MAP_TEXTURE_SIZE : GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throwGpu("texture size {}x{} is beyond the driver's {} ({})", width, height,
             cube ? "GL_MAX_CUBE_MAP_TEXTURE_SIZE" : "GL_MAX_TEXTURE_SIZE", max_size);
  const bool array = target == GL_TEXTURE_2D_ARRAY || target == GL_TEXTURE_CUBE_MAP_ARRAY;
  if (array && (layers < 1 || layers > max_layers))
    throwGpu("a texture of {} layers is beyond the driver's GL_MAX_ARRAY_TEXTURE_LAYERS ({})",
             layers, max_layers);
}

// Large storage may be more than the GPU (or llvmpipe's host memory) holds: the driver says so
// with GL_OUT_OF_MEMORY, which is asked only for allocations worth asking about.
void checkAllocated(GLenum format, int width, int height, int layers) {
  const uint64_t bytes = uint64_t(width) * uint64_t(height) * uint64_t(layers) * texelBytes(format);
  if (bytes < (uint64_t(256) << 20)) return;
  if (glGetError() == GL_OUT_OF_MEMORY)
    throwGpu(
        "a {}x{}x{} texture ({} MiB) is more than the driver could allocate (GL_OUT_OF_MEMORY)",
        width, height, layers, bytes >> 20);
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

Texture Texture::overBuffer(GLenum internal_format, const Buffer& buffer) {
  const uint64_t texels = buffer.size() / texelBytes(internal_format);
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &largest);
  if (texels > uint64_t(largest))
    throwGpu("a buffer texture of {} texels is beyond the driver's GL_MAX_TEXTURE_BUFFER_SIZE ({})",
             texels, largest);
  // Buffer textures have no sampling state: the constructor's defaults are not set.
  Texture t(0, internal_format, {int(texels), 1}, 1, 1);
  t.target_ = GL_TEXTURE_BUFFER;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
  t.handle_ = Handle<TextureTraits>(id);
  glTextureBuffer(id, internal_format, buffer.id());
  return t;
}

int Texture::fullMipLevels(int size) {
  return std::bit_width(unsigned(std::max(size, 1)));
}

Texture Texture::create2D(GLenum internal_format, int width, int height, int levels) {
  checkSize(GL_TEXTURE_2D, width, height, 1);
  Texture t(GL_TEXTURE_2D, internal_format, {width, height}, 1, levels);
  glTextureStorage2D(t.id(), levels, internal_format, width, height);
  t.charge_ = MemoryCharge(gpu::storageBytes(internal_format, width, height, 1, levels));
  checkAllocated(internal_format, width, height, 1);
  return t;
}

Texture Texture::create2DArray(GLenum internal_format, int width, int height, int layers,
                               int levels) {
  checkSize(GL_TEXTURE_2D_ARRAY, width, height, layers);
  Texture t(GL_TEXTURE_2D_ARRAY, internal_format, {width, height}, layers, levels);
  glTextureStorage3D(t.id(), levels, internal_format, width, height, layers);
  t.charge_ = MemoryCharge(gpu::storageBytes(internal_format, width, height, layers, levels));
  checkAllocated(internal_format, width, height, layers);
  return t;
}

Texture Texture::createCube(GLenum internal_format, int size, int levels) {
  checkSize(GL_TEXTURE_CUBE_MAP, size, size, 6);
  Texture t(GL_TEXTURE_CUBE_MAP, internal_format, {size, size}, 6, levels);
  glTextureStorage2D(t.id(), levels, internal_format, size, size);
  t.charge_ = MemoryCharge(gpu::storageBytes(internal_format, size, size, 6, levels));
  checkAllocated(internal_format, size, size, 6);
  return t;
}

Texture Texture::createCubeArray(GLenum internal_format, int size, int cubes, int levels) {
  checkSize(GL_TEXTURE_CUBE_MAP_ARRAY, size, size, 6 * cubes);
  Texture t(GL_TEXTURE_CUBE_MAP_ARRAY, internal_format, {size, size}, 6 * cubes, levels);
  glTextureStorage3D(t.id(), levels, internal_format, size, size, 6 * cubes);
  t.charge_ = MemoryCharge(gpu::storageBytes(internal_format, size, size, 6 * cubes, levels));
  checkAllocated(internal_format, size, size, 6 * cubes);
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

void Texture::generateMipmaps(int first_layer, int layers) {
  if (levels_ <= 1) return;
  if (first_layer == 0 && layers == layers_) return generateMipmaps();
  if (first_layer < 0 || layers < 0 || first_layer + layers > layers_)
    throwRuntime("mip chain of layers {}..{} of a {}-layer texture", first_layer,
                 first_layer + layers - 1, layers_);
  // Each level from the one above by a linear 2:1 blit, layer by layer (a texture view per
  // layer, as glGenerateTextureMipmap would need, costs llvmpipe far more than the blits).
  Framebuffer read, draw;
  for (int layer = first_layer; layer < first_layer + layers; ++layer)
    for (int level = 1; level < levels_; ++level) {
      const ivec2 from = glm::max(size_ >> (level - 1), ivec2(1));
      const ivec2 to = glm::max(size_ >> level, ivec2(1));
      read.attachColor(0, *this, level - 1, layer);
      draw.attachColor(0, *this, level, layer);
      glBlitNamedFramebuffer(read.id(), draw.id(), 0, 0, from.x, from.y, 0, 0, to.x, to.y,
                             GL_COLOR_BUFFER_BIT, GL_LINEAR);
    }
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
