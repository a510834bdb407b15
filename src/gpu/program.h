// Linked GLSL programs built from shader files (see shader_source.h), with uniform setters.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "gpu/handle.h"

namespace mirage::gpu {

class Program {
 public:
  Program() = default;

  // A vertex + fragment program. `defines` are "NAME" or "NAME VALUE" strings.
  static Program graphics(const std::string& vertex_path, const std::string& fragment_path,
                          const std::vector<std::string>& defines = {});
  static Program compute(const std::string& path, const std::vector<std::string>& defines = {});

  GLuint id() const { return handle_.id(); }
  explicit operator bool() const { return bool(handle_); }
  void use() const { glUseProgram(id()); }

  GLint location(const char* name) const { return glGetUniformLocation(id(), name); }
  void set(const char* name, int v) const { glProgramUniform1i(id(), location(name), v); }
  void set(const char* name, float v) const { glProgramUniform1f(id(), location(name), v); }
  void set(const char* name, const vec2& v) const;
  void set(const char* name, const vec3& v) const;
  void set(const char* name, const vec4& v) const;
  void set(const char* name, const ivec2& v) const;
  void set(const char* name, const ivec4& v) const;
  void set(const char* name, const mat4& v) const;

 private:
  Handle<ProgramTraits> handle_;
};

}  // namespace mirage::gpu
