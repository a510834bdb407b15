// GPU buffers (DSA). Fixed-size storage or resizable data stores, uploads and indexed binding.
#pragma once

#include <cstddef>
#include <span>

#include "gpu/handle.h"
#include "gpu/memory.h"

namespace mirage::gpu {

class Buffer {
 public:
  Buffer() = default;
  // A mutable data store of `bytes` (optionally initialised), usage GL_DYNAMIC_DRAW.
  explicit Buffer(size_t bytes, const void* data = nullptr);

  template <typename T>
  static Buffer fromSpan(std::span<const T> items) {
    return Buffer(items.size_bytes(), items.data());
  }

  GLuint id() const { return handle_.id(); }
  size_t size() const { return size_; }

  // Uploads at `offset`; grows the buffer (discarding contents) if it does not fit.
  void upload(const void* data, size_t bytes, size_t offset = 0);
  template <typename T>
  void upload(std::span<const T> items) {
    upload(items.data(), items.size_bytes());
  }
  template <typename T>
  void uploadValue(const T& value) {
    upload(&value, sizeof(T));
  }
  // Reads back `bytes` from `offset` (synchronous).
  void download(void* data, size_t bytes, size_t offset = 0) const;

  // glBindBufferBase for GL_UNIFORM_BUFFER / GL_SHADER_STORAGE_BUFFER / ...
  void bindBase(GLenum target, GLuint index) const;

 private:
  Handle<BufferTraits> handle_;
  MemoryCharge charge_;  // its data store
  size_t size_ = 0;
};

}  // namespace mirage::gpu
