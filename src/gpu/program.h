// Linked GLSL programs built from shader files (see shader_source.h), with uniform setters.
//
// A uniform name that a program neither has active nor declares anywhere in its sources is a
// misspelling, which GL answers by ignoring the call. With the uniform checks on (debug builds,
// MIRAGE_GL_CHECK_UNIFORMS=1, or setUniformChecks(true), which the tests' main calls) set()
// throws RuntimeError naming the program and the name instead (for programs made while the
// checks are on: only they keep their sources). A declared uniform that the compiler removed
// (unused under this program's defines) stays a silent no-op, as GL has it.
#pragma once

#include <map>
#include <memory>
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

  // The uniform's location, -1 where it is inactive; with the checks on, throws for a name the
  // sources do not declare.
  GLint location(const char* name) const;
  void set(const char* name, int v) const { glProgramUniform1i(id(), location(name), v); }
  void set(const char* name, float v) const { glProgramUniform1f(id(), location(name), v); }
  void set(const char* name, const vec2& v) const;
  void set(const char* name, const vec3& v) const;
  void set(const char* name, const vec4& v) const;
  void set(const char* name, const ivec2& v) const;
  void set(const char* name, const ivec4& v) const;
  void set(const char* name, const mat4& v) const;

 private:
  struct Sources {
    std::string what;  // the shader paths, for messages
    std::string text;  // every stage's expanded source
    // Every name declared `uniform`, sorted: read from `text` when a set() first misses.
    std::vector<std::string> uniforms;
    bool scanned = false;
  };
  static Program linked(const std::vector<GLuint>& shaders, Sources sources);

  Handle<ProgramTraits> handle_;
  std::shared_ptr<Sources> sources_;
};

// The shader files (paths under src/) this process has compiled a stage from, with how many
// times: what the test of every program's variants checks it reached
// (tests/methods/every_program_test.cpp).
std::map<std::string, long long> compiledShaderFiles();

bool uniformChecks();
void setUniformChecks(bool on);

// The names a GLSL text declares `uniform` (`uniform T a;`, `uniform T a, b[4] = ...;`, after
// layout, precision and memory qualifiers; not uniform blocks), in order, comments skipped.
std::vector<std::string> declaredUniforms(const std::string& glsl);

}  // namespace mirage::gpu
