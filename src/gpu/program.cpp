#include "gpu/program.h"

#include "core/error.h"
#include "gpu/shader_source.h"

namespace mirage::gpu {

namespace {

Handle<ShaderTraits> compileStage(GLenum stage, const std::string& path,
                                  const std::vector<std::string>& defines) {
  ShaderSource source = loadShaderSource(path, defines);
  Handle<ShaderTraits> shader(glCreateShader(stage));
  const char* text = source.text.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
    throwGpu("shader '{}' does not compile:\n{}", path,
             annotateShaderLog(log.c_str(), source.files));
  }
  return shader;
}

Handle<ProgramTraits> link(const std::vector<GLuint>& shaders, const std::string& what) {
  Handle<ProgramTraits> program(glCreateProgram());
  for (GLuint s : shaders) glAttachShader(program.id(), s);
  glLinkProgram(program.id());
  for (GLuint s : shaders) glDetachShader(program.id(), s);
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.id(), length, nullptr, log.data());
    throwGpu("program '{}' does not link:\n{}", what, log.c_str());
  }
  return program;
}

}  // namespace

Program Program::graphics(const std::string& vertex_path, const std::string& fragment_path,
                          const std::vector<std::string>& defines) {
  auto vs = compileStage(GL_VERTEX_SHADER, vertex_path, defines);
  auto fs = compileStage(GL_FRAGMENT_SHADER, fragment_path, defines);
  Program p;
  p.handle_ = link({vs.id(), fs.id()}, vertex_path + " + " + fragment_path);
  return p;
}

Program Program::compute(const std::string& path, const std::vector<std::string>& defines) {
  auto cs = compileStage(GL_COMPUTE_SHADER, path, defines);
  Program p;
  p.handle_ = link({cs.id()}, path);
  return p;
}

void Program::set(const char* name, const vec2& v) const {
  glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const vec3& v) const {
  glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const vec4& v) const {
  glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const ivec2& v) const {
  glProgramUniform2iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const ivec4& v) const {
  glProgramUniform4iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const mat4& v) const {
  glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace mirage::gpu
