// Move-only ownership of one OpenGL object name; Traits::destroy deletes it. Every handle of a
// kind is counted while it lives (single GL thread), so that tests can prove that making and
// dropping methods leaks nothing (gpu/object_count.h counts what GL itself holds as well).
#pragma once

#include <algorithm>
#include <utility>

#include "gpu/gl.h"

namespace mirage::gpu {

// The largest object name any handle has held: how far gpu/object_count.h probes.
inline GLuint& largestHandleName() {
  static GLuint largest = 0;
  return largest;
}

template <typename Traits>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {
    if (id_) {
      ++live();
      largestHandleName() = std::max(largestHandleName(), id_);
    }
  }
  // Handles of this kind alive now.
  static long& live() {
    static long count = 0;
    return count;
  }
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
    if (id_) {
      Traits::destroy(id_);
      --live();
    }
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
