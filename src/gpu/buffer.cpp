#include "gpu/buffer.h"

#include "core/error.h"

namespace mirage::gpu {

Buffer::Buffer(size_t bytes, const void* data) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  handle_ = Handle<BufferTraits>(id);
  size_ = bytes;
  glNamedBufferData(id, GLsizeiptr(bytes ? bytes : 16), data, GL_DYNAMIC_DRAW);
}

void Buffer::upload(const void* data, size_t bytes, size_t offset) {
  if (!handle_ || offset + bytes > size_) {
    if (offset != 0) throwRuntime("buffer upload at offset {} past its size {}", offset, size_);
    *this = Buffer(bytes, data);
    return;
  }
  if (bytes) glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::download(void* data, size_t bytes, size_t offset) const {
  if (offset + bytes > size_) throwRuntime("buffer download past its size {}", size_);
  glGetNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::bindBase(GLenum target, GLuint index) const {
  glBindBufferBase(target, index, id());
}

}  // namespace mirage::gpu
