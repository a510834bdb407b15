// Move-only ownership of one OpenGL object name; Traits::destroy deletes it.
#pragma once

#include <utility>

#include "gpu/gl.h"

namespace mirage::gpu {

template <typename Traits>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Traits::destroy(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct BufferTraits {
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct TextureTraits {
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferTraits {
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayTraits {
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct ProgramTraits {
  static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderTraits {
  static void destroy(GLuint id) { glDeleteShader(id); }
};
struct QueryTraits {
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

// A new vertex array object (empty: attribute-less draws, or set up by the caller).
inline Handle<VertexArrayTraits> createVertexArray() {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  return Handle<VertexArrayTraits>(vao);
}

}  // namespace mirage::gpu
