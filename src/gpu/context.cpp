#include "gpu/context.h"

#include <cstdlib>
#include <cstring>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "gpu/gl.h"

namespace mirage::gpu {

namespace {

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                              const GLchar* message, const void*) {
  (void)source;
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  auto level = type == GL_DEBUG_TYPE_ERROR ? spdlog::level::err : spdlog::level::warn;
  spdlog::log(level, "GL debug [{}]: {}", id, message);
}

}  // namespace

bool debugSwitch(const char* name) {
  if (const char* env = std::getenv(name)) return std::strcmp(env, "0") != 0;
#ifdef NDEBUG
  return false;
#else
  return true;
#endif
}

bool debugContextByDefault() {
  return debugSwitch("MIRAGE_GL_DEBUG");
}

bool isSoftwareRenderer(const std::string& renderer) {
  for (const char* soft : {"llvmpipe", "softpipe", "swrast", "SwiftShader"})
    if (renderer.find(soft) != std::string::npos) return true;
  return false;
}

bool currentContextIsSoftware() {
  const GLubyte* s = glGetString(GL_RENDERER);
  return s && isSoftwareRenderer(reinterpret_cast<const char*>(s));
}

void Context::queryInfo(const std::string& platform) {
  auto str = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  info_.platform = platform;
  info_.vendor = str(GL_VENDOR);
  info_.renderer = str(GL_RENDERER);
  info_.version = str(GL_VERSION);
  glGetIntegerv(GL_MAJOR_VERSION, &info_.major);
  glGetIntegerv(GL_MINOR_VERSION, &info_.minor);
  info_.software = isSoftwareRenderer(info_.renderer);
  if (info_.major * 10 + info_.minor < 45)
    throw NoOpenGLError("OpenGL 4.5 core is required, the driver gives " + info_.version + " (" +
                        info_.renderer + ")");
}

void Context::enableDebugOutput() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debugCallback, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

}  // namespace mirage::gpu
