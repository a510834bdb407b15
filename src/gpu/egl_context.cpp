// Headless OpenGL through EGL. Platforms are tried in order: Mesa's surfaceless platform (no
// display server, llvmpipe or a GPU), the device platform (NVIDIA's driver), the default display.
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <epoxy/egl.h>
#include <fmt/format.h>

#include "core/error.h"
#include "gpu/context.h"
#include "gpu/gl.h"
#include "gpu/keep_drivers_loaded.h"

namespace mirage::gpu {

namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay display, EGLContext context, EGLSurface surface)
      : display_(display), context_(context), surface_(surface) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  void makeCurrent() override {
    if (!eglMakeCurrent(display_, surface_, surface_, context_))
      throwRuntime("eglMakeCurrent failed (0x{:x})", eglGetError());
  }
  void finishSetup(const std::string& platform, bool debug) {
    makeCurrent();
    queryInfo(platform);
    if (debug) enableDebugOutput();
  }

 private:
  EGLDisplay display_;
  EGLContext context_;
  EGLSurface surface_;
};

// Creates a 4.5 core context on an initialised display; returns nullptr and a reason on failure.
std::unique_ptr<EglContext> createOn(EGLDisplay display, bool debug, std::string& why) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    why = fmt::format("eglInitialize failed (0x{:x})", eglGetError());
    return nullptr;
  }
  keepDriversLoaded();
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "the display has no desktop OpenGL API";
    eglTerminate(display);
    return nullptr;
  }
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  EGLConfig config = EGL_NO_CONFIG_KHR;
  EGLSurface surface = EGL_NO_SURFACE;
  bool no_config = hasExtension(extensions, "EGL_KHR_no_config_context");
  bool surfaceless = hasExtension(extensions, "EGL_KHR_surfaceless_context");
  if (!no_config || !surfaceless) {
    const EGLint attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                 EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, attributes, &config, 1, &count) || count == 0) {
      why = "no EGL config renders desktop OpenGL";
      eglTerminate(display);
      return nullptr;
    }
  }
  std::vector<EGLint> attributes = {
      EGL_CONTEXT_MAJOR_VERSION,       4,
      EGL_CONTEXT_MINOR_VERSION,       5,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
  if (debug) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
  attributes.push_back(EGL_NONE);
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
  if (context == EGL_NO_CONTEXT) {
    why = fmt::format("no OpenGL 4.5 core context (eglCreateContext: 0x{:x})", eglGetError());
    eglTerminate(display);
    return nullptr;
  }
  if (!surfaceless) {
    const EGLint pbuffer[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer);
  }
  return std::make_unique<EglContext>(display, context, surface);
}

}  // namespace

std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options) {
  if (const char* env = std::getenv("MIRAGE_NO_GL"); env && std::strcmp(env, "0") != 0)
    throw NoOpenGLError("no OpenGL 4.5 driver: MIRAGE_NO_GL is set");

  struct Candidate {
    std::string name;
    std::function<EGLDisplay()> open;
  };
  std::vector<Candidate> candidates;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  bool platform_base = hasExtension(client, "EGL_EXT_platform_base");
  if (platform_base && hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    candidates.push_back({"EGL surfaceless", [] {
                            return eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA,
                                                            EGL_DEFAULT_DISPLAY, nullptr);
                          }});
  }
  if (platform_base && hasExtension(client, "EGL_EXT_platform_device")) {
    candidates.push_back({"EGL device", [] {
                            EGLDeviceEXT devices[8];
                            EGLint count = 0;
                            if (!eglQueryDevicesEXT(8, devices, &count) || count == 0)
                              return EGLDisplay(EGL_NO_DISPLAY);
                            return eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0],
                                                            nullptr);
                          }});
  }
  candidates.push_back({"EGL default display", [] { return eglGetDisplay(EGL_DEFAULT_DISPLAY); }});

  std::string reasons;
  for (const Candidate& candidate : candidates) {
    EGLDisplay display = candidate.open();
    std::string why = "no display";
    if (display != EGL_NO_DISPLAY) {
      if (auto context = createOn(display, options.debug, why)) {
        try {
          context->finishSetup(candidate.name, options.debug);
          return context;
        } catch (const NoOpenGLError& e) {
          why = e.what();
        }
      }
    }
    reasons += fmt::format("\n  {}: {}", candidate.name, why);
  }
  throw NoOpenGLError(
      "no OpenGL 4.5 core driver found (install Mesa: libegl-mesa0 "
      "libgl1-mesa-dri, or a GPU driver). Tried:" +
      reasons);
}

}  // namespace mirage::gpu
