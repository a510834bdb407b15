#include "gpu/memory.h"

#include <algorithm>

namespace mirage::gpu {

namespace {

int64_t& held() {
  static int64_t bytes = 0;
  return bytes;
}

}  // namespace

int64_t allocatedBytes() {
  return held();
}

uint64_t texelBytes(GLenum internal_format) {
  switch (internal_format) {
    case GL_R8:
      return 1;
    case GL_R16F:
      return 2;
    case GL_R32F:
    case GL_R32UI:
    case GL_RG16F:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH24_STENCIL8:
    case GL_RGBA8:
      return 4;
    case GL_RG32F:
    case GL_RG32UI:
    case GL_RGBA16F:
      return 8;
    case GL_RGB32F:
      return 12;
    default:
      return 16;
  }
}

uint64_t storageBytes(GLenum internal_format, int width, int height, int layers, int levels) {
  uint64_t texels = 0;
  for (int l = 0; l < levels; ++l)
    texels += uint64_t(std::max(width >> l, 1)) * uint64_t(std::max(height >> l, 1));
  return texels * uint64_t(std::max(layers, 0)) * texelBytes(internal_format);
}

MemoryCharge::MemoryCharge(uint64_t bytes) : bytes_(bytes) {
  held() += int64_t(bytes_);
}

MemoryCharge::~MemoryCharge() {
  held() -= int64_t(bytes_);
}

MemoryCharge& MemoryCharge::operator=(MemoryCharge&& other) noexcept {
  if (this != &other) {
    held() -= int64_t(bytes_);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

}  // namespace mirage::gpu
