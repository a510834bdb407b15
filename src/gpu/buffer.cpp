#include "gpu/buffer.h"

#include "core/error.h"

namespace mirage::gpu {

Buffer::Buffer(size_t bytes, const void* data) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  handle_ = Handle<BufferTraits>(id);
  size_ = bytes;
  glNamedBufferData(id, GLsizeiptr(bytes ? bytes : 16), data, GL_DYNAMIC_DRAW);
  charge_ = MemoryCharge(bytes ? bytes : 16);
  // Asked only for allocations worth asking about (see Texture's checkAllocated).
  if (bytes >= (size_t(256) << 20) && glGetError() == GL_OUT_OF_MEMORY)
    throwGpu("a buffer of {} MiB is more than the driver could allocate (GL_OUT_OF_MEMORY)",
             bytes >> 20);
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
  // A shader sees at most the driver's block size of a buffer; one bound past it would be read
  // cut short, so it is refused (the frame renderer then falls back to envmap).
  if (target == GL_SHADER_STORAGE_BUFFER || target == GL_UNIFORM_BUFFER) {
    const bool storage = target == GL_SHADER_STORAGE_BUFFER;
    GLint64 largest = 0;
    glGetInteger64v(storage ? GL_MAX_SHADER_STORAGE_BLOCK_SIZE : GL_MAX_UNIFORM_BLOCK_SIZE,
                    &largest);
    if (largest > 0 && size_ > size_t(largest))
      throwGpu("a {} buffer of {} bytes is beyond the driver's {} ({})",
               storage ? "storage" : "uniform", size_,
               storage ? "GL_MAX_SHADER_STORAGE_BLOCK_SIZE" : "GL_MAX_UNIFORM_BLOCK_SIZE", largest);
  }
  glBindBufferBase(target, index, id());
}

}  // namespace mirage::gpu
