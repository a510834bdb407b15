// OpenGL 4.5 core contexts: a headless EGL one (surfaceless Mesa, NVIDIA's device platform, or
// the default display) for the command-line tools and tests, and a GLFW window for the viewer.
#pragma once

#include <memory>
#include <string>

namespace mirage::gpu {

struct GlInfo {
  std::string vendor, renderer, version, platform;
  int major = 0, minor = 0;
  bool software = false;  // llvmpipe/softpipe/swrast: timer queries measure submission only
};

class Context {
 public:
  virtual ~Context() = default;
  virtual void makeCurrent() = 0;
  const GlInfo& info() const { return info_; }

 protected:
  // Reads the version strings of the current context; throws NoOpenGLError below 4.5.
  void queryInfo(const std::string& platform);
  // Enables KHR_debug output (debug builds, or MIRAGE_GL_DEBUG=1).
  void enableDebugOutput();

  GlInfo info_;
};

// The renderer string names a software rasteriser (llvmpipe, softpipe, swrast, SwiftShader).
bool isSoftwareRenderer(const std::string& renderer);
// The same for the current context.
bool currentContextIsSoftware();

struct ContextOptions {
  bool debug = false;  // request a debug context and print KHR_debug messages
};

// A debugging aid's default: the environment variable `name` when set ("0" off, anything else
// on), otherwise on in debug builds and off in release builds.
bool debugSwitch(const char* name);
// The default debug setting: on in debug builds and when MIRAGE_GL_DEBUG=1.
bool debugContextByDefault();

// Creates a headless OpenGL 4.5 core context and makes it current. Throws NoOpenGLError (exit
// code 3) with the reasons of every platform tried when none gives 4.5 core. MIRAGE_NO_GL=1
// pretends no driver exists (to test that path).
std::unique_ptr<Context> createHeadlessContext(const ContextOptions& options = {});

}  // namespace mirage::gpu
