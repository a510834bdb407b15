// GPU storage accounting: the bytes of texture and buffer storage mirage holds now, so that a
// benchmark can say what each method allocated (`gpu_bytes` in the bench JSON). Computed from
// what was asked of the driver (levels × layers × texels × bytes per texel), not read from it:
// OpenGL has no portable query of an object's memory. Single GL thread, like gpu/handle.h.
#pragma once

#include <cstdint>
#include <utility>

#include "gpu/gl.h"

namespace mirage::gpu {

// Bytes of storage held by every live Texture and Buffer (texture views and buffer textures
// share storage and add nothing).
int64_t allocatedBytes();

// Bytes per texel of an internal format (16 for a format not listed: an upper bound).
uint64_t texelBytes(GLenum internal_format);
// Bytes of `levels` mip levels of `layers` layers of width × height texels.
uint64_t storageBytes(GLenum internal_format, int width, int height, int layers, int levels);

// Adds its bytes to allocatedBytes() while it lives; moves with the object that owns it.
class MemoryCharge {
 public:
  MemoryCharge() = default;
  explicit MemoryCharge(uint64_t bytes);
  ~MemoryCharge();
  MemoryCharge(MemoryCharge&& other) noexcept : bytes_(std::exchange(other.bytes_, 0)) {}
  MemoryCharge& operator=(MemoryCharge&& other) noexcept;
  MemoryCharge(const MemoryCharge&) = delete;
  MemoryCharge& operator=(const MemoryCharge&) = delete;

  uint64_t bytes() const { return bytes_; }

 private:
  uint64_t bytes_ = 0;
};

}  // namespace mirage::gpu
