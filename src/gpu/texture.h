// GPU textures (DSA, immutable storage): 2D, 2D arrays, cube maps and cube-map arrays; and buffer
// textures over a gpu::Buffer's storage.
#pragma once

#include "core/math.h"
#include "gpu/buffer.h"
#include "gpu/handle.h"
#include "gpu/memory.h"

namespace mirage::gpu {

class Texture {
 public:
  Texture() = default;

  static Texture create2D(GLenum internal_format, int width, int height, int levels = 1);
  static Texture create2DArray(GLenum internal_format, int width, int height, int layers,
                               int levels = 1);
  static Texture createCube(GLenum internal_format, int size, int levels = 1);
  static Texture createCubeArray(GLenum internal_format, int size, int cubes, int levels = 1);
  // The number of levels of a full mip chain for the given largest side.
  static int fullMipLevels(int size);
  // A view of `layers` layers of `source` from `first_layer`, all its levels, as `target`
  // (GL_TEXTURE_2D for one layer, GL_TEXTURE_2D_ARRAY for several): the same storage, so that a
  // pass written for a 2D texture or a whole array can work on part of a larger array.
  static Texture view(const Texture& source, GLenum target, int first_layer, int layers);
  // A buffer texture: `buffer`'s storage read as texels of `internal_format` (texelFetch on a
  // samplerBuffer), no copy. A shader reading a storage buffer it does not write is better served
  // so on llvmpipe, which loads a storage buffer lane by lane but fetches texels as vectors.
  // Throws a GpuError where the buffer holds more texels than the driver's
  // GL_MAX_TEXTURE_BUFFER_SIZE.
  static Texture overBuffer(GLenum internal_format, const Buffer& buffer);

  GLuint id() const { return handle_.id(); }
  GLenum target() const { return target_; }
  GLenum internalFormat() const { return format_; }
  ivec2 size() const { return size_; }
  int layers() const { return layers_; }
  int levels() const { return levels_; }
  // Bytes of the storage it allocated (0 for a view or a buffer texture).
  uint64_t storageBytes() const { return charge_.bytes(); }

  // Uploads a level of a 2D texture.
  void upload(int level, GLenum format, GLenum type, const void* pixels);
  // Uploads one layer (array layer, cube face, or layer-face = 6 * cube + face) of a level.
  void uploadLayer(int level, int layer, GLenum format, GLenum type, const void* pixels);
  // Uploads `count` consecutive layers of a level from one block of memory.
  void uploadLayers(int level, int first_layer, int count, GLenum format, GLenum type,
                    const void* pixels);
  // Reads one layer of a level back (`bytes`: the size of `out`, checked by GL).
  void downloadLayer(int level, int layer, GLenum format, GLenum type, void* out,
                     size_t bytes) const;
  void generateMipmaps();
  // The mip chain of `layers` layers from `first_layer` only (of an array; a cube-map array's
  // layers are its faces): a moving scene re-captures a few layers of a large array, and
  // rebuilding every layer's chain would cost more than they did. Linear 2:1 blits, level by
  // level; glGenerateTextureMipmap's filter may differ in the last bits.
  void generateMipmaps(int first_layer, int layers);
  void setFilter(GLenum min_filter, GLenum mag_filter);
  void setWrap(GLenum wrap);
  void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }

 private:
  Texture(GLenum target, GLenum format, ivec2 size, int layers, int levels);
  void setDefaultSampling();

  Handle<TextureTraits> handle_;
  MemoryCharge charge_;  // its storage (none for a view or a buffer texture)
  GLenum target_ = 0, format_ = 0;
  ivec2 size_{0};
  int layers_ = 0, levels_ = 0;
};

}  // namespace mirage::gpu
