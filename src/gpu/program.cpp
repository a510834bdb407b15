#include "gpu/program.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <map>
#include <mutex>
#include <regex>

#include <fmt/format.h>

#include "core/error.h"
#include "gpu/context.h"
#include "gpu/shader_source.h"

namespace mirage::gpu {

namespace {

// The text with each comment replaced by a space (by hand: libstdc++'s regex recurses per
// character of a match, too deep for a long block comment).
std::string withoutComments(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
    } else if (text.compare(i, 2, "/*") == 0) {
      const size_t end = text.find("*/", i + 2);
      i = end == std::string::npos ? text.size() : end + 2;
      out += ' ';
    } else {
      out += text[i++];
    }
  }
  return out;
}

std::atomic<bool>& uniformChecksFlag() {
  static std::atomic<bool> on{debugSwitch("MIRAGE_GL_CHECK_UNIFORMS")};
  return on;
}

std::mutex& compiledMutex() {
  static std::mutex m;
  return m;
}
std::map<std::string, long long>& compiledPaths() {
  static std::map<std::string, long long> paths;
  return paths;
}
void noteCompiled(const std::string& path) {
  std::lock_guard lock(compiledMutex());
  ++compiledPaths()[path];
}

// The compiler's or linker's messages about a shader or a program.
std::string infoLog(GLuint id, bool is_program) {
  GLint length = 0;
  (is_program ? glGetProgramiv : glGetShaderiv)(id, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  (is_program ? glGetProgramInfoLog : glGetShaderInfoLog)(id, length, nullptr, log.data());
  return log;
}

Handle<ShaderTraits> compileStage(GLenum stage, const std::string& path,
                                  const std::vector<std::string>& defines, std::string& all_text) {
  ShaderSource source = loadShaderSource(path, defines);
  if (uniformChecks()) all_text += source.text;  // kept only where set() will check names
  Handle<ShaderTraits> shader(glCreateShader(stage));
  const char* text = source.text.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok)
    throw ShaderError(fmt::format("shader '{}' does not compile:\n{}", path,
                                  annotateShaderLog(infoLog(shader.id(), false).c_str(),
                                                    source.files)));
  noteCompiled(path);
  return shader;
}

Handle<ProgramTraits> link(const std::vector<GLuint>& shaders, const std::string& what) {
  Handle<ProgramTraits> program(glCreateProgram());
  for (GLuint s : shaders) glAttachShader(program.id(), s);
  glLinkProgram(program.id());
  for (GLuint s : shaders) glDetachShader(program.id(), s);
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok)
    throw ShaderError(
        fmt::format("program '{}' does not link:\n{}", what, infoLog(program.id(), true).c_str()));
  return program;
}

}  // namespace

Program Program::linked(const std::vector<GLuint>& shaders, Sources sources) {
  Program p;
  p.handle_ = link(shaders, sources.what);
  p.sources_ = std::make_shared<Sources>(std::move(sources));
  return p;
}

Program Program::graphics(const std::string& vertex_path, const std::string& fragment_path,
                          const std::vector<std::string>& defines) {
  Sources sources;
  sources.what = vertex_path + " + " + fragment_path;
  auto vs = compileStage(GL_VERTEX_SHADER, vertex_path, defines, sources.text);
  auto fs = compileStage(GL_FRAGMENT_SHADER, fragment_path, defines, sources.text);
  return linked({vs.id(), fs.id()}, std::move(sources));
}

Program Program::compute(const std::string& path, const std::vector<std::string>& defines) {
  Sources sources;
  sources.what = path;
  auto cs = compileStage(GL_COMPUTE_SHADER, path, defines, sources.text);
  return linked({cs.id()}, std::move(sources));
}

GLint Program::location(const char* name) const {
  const GLint at = glGetUniformLocation(id(), name);
  if (at >= 0 || !sources_ || sources_->text.empty() || !uniformChecks()) return at;
  if (!sources_->scanned) {
    sources_->uniforms = declaredUniforms(sources_->text);
    std::sort(sources_->uniforms.begin(), sources_->uniforms.end());
    sources_->scanned = true;
  }
  // "u_a[2]" and "u_s.field" are declared as u_a and u_s.
  const std::string base(name, std::strcspn(name, "[."));
  if (!std::binary_search(sources_->uniforms.begin(), sources_->uniforms.end(), base))
    throwRuntime("program '{}': set() of uniform '{}', which its sources do not declare",
                 sources_->what, name);
  return at;
}

std::map<std::string, long long> compiledShaderFiles() {
  std::lock_guard lock(compiledMutex());
  return compiledPaths();
}

bool uniformChecks() {
  return uniformChecksFlag().load();
}
void setUniformChecks(bool on) {
  uniformChecksFlag().store(on);
}

std::vector<std::string> declaredUniforms(const std::string& glsl) {
  // `uniform`, then up to the semicolon: a type and declarators, or a block (`Name {`: skipped).
  static const std::regex declaration(R"(\buniform\s+([^;{]*);)");
  static const std::regex qualifier(
      R"(^(?:(?:lowp|mediump|highp|restrict|readonly|writeonly|coherent|volatile)\s+)*)");
  static const std::regex declarator(R"(([A-Za-z_]\w*)\s*(?:\[[^\]]*\]\s*)*(?:=[^,]*)?(?:,|$))");
  const std::string code = withoutComments(glsl);
  std::vector<std::string> names;
  for (std::sregex_iterator it(code.begin(), code.end(), declaration), end; it != end; ++it) {
    std::string rest = std::regex_replace((*it)[1].str(), qualifier, "");
    // Drop the type (its first word, with any array suffix), keep the declarators.
    const size_t type_end = rest.find_first_of(" \t\n");
    if (type_end == std::string::npos) continue;
    rest = rest.substr(type_end);
    for (std::sregex_iterator d(rest.begin(), rest.end(), declarator), e; d != e; ++d)
      names.push_back((*d)[1].str());
  }
  return names;
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
