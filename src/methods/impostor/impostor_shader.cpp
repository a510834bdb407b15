#include "methods/impostor/impostor_shader.h"

#include <utility>

namespace mirage {

namespace {

constexpr Choice<ReflectorPass> kPasses[] = {{"auto", ReflectorPass::kAuto},
                                             {"screen", ReflectorPass::kScreen},
                                             {"triangles", ReflectorPass::kTriangles}};

gpu::Program compile(const char* vertex, const char* fragment, std::vector<std::string> defines,
                     bool screen) {
  if (screen) defines.push_back("MIRAGE_REFLECTOR_SCREEN 1");
  return gpu::Program::graphics(vertex, fragment, defines);
}

}  // namespace

ParamSpec impostorPassParam() {
  return ParamSpec::choice<ReflectorPass>(
      "impostor-pass", kPasses, ReflectorPass::kAuto,
      "how a reflector's pixels are traced after one pass over the reflectors writes their depth "
      "and normals: screen, a screen-space pass over its screen rectangle; triangles, a second "
      "pass over its triangles at that depth; auto: the screen pass where its triangles cover "
      "fewer than 8 pixels of the rectangle each (the same pixels either way)");
}

ReflectorPass impostorPass(const ParamValues& params) {
  return params.choice<ReflectorPass>("impostor-pass", kPasses);
}

void addPassStats(std::map<std::string, double>& stats, const ReflectorPasses& passes) {
  stats["impostor_screen_reflectors"] = double(passes.screen);
  stats["impostor_triangle_reflectors"] = double(passes.triangles);
}

ImpostorShader::ImpostorShader(const char* fragment, std::vector<std::string> defines,
                               ReflectorPass pass)
    : pass_(pass) {
  if (pass_ != ReflectorPass::kTriangles)
    screen_ = compile("render/shaders/fullscreen.vert", fragment, defines, true);
  if (pass_ != ReflectorPass::kScreen)
    triangles_ = compile("render/shaders/scene.vert", fragment, std::move(defines), false);
}

std::vector<const gpu::Program*> ImpostorShader::programs() const {
  std::vector<const gpu::Program*> out;
  if (pass_ != ReflectorPass::kTriangles) out.push_back(&screen_);
  if (pass_ != ReflectorPass::kScreen) out.push_back(&triangles_);
  return out;
}

ReflectorPasses ImpostorShader::draw(FrameContext& frame, ReflectorGBuffer& gbuffer) const {
  ShadeOptions options;
  options.own = frame.own;
  options.triangles = pass_ != ReflectorPass::kScreen ? &triangles_ : nullptr;
  options.pass = pass_;  // kTriangles: the screen program is not compiled, nor used
  const ReflectorPlan plan = gbuffer.plan(frame.gpu, frame.view, options);
  if (plan.taken.screen > 0) {
    gbuffer.begin(frame.target, frame.passes, frame.view, frame.settings);
    frame.drawOwnReflectors(gbuffer.reflectorProgram());
  } else {
    // Nothing for the screen pass: the reflectors' depth alone, for the pass over their
    // triangles (it writes the rest), and no G-buffer to clear and fill. The colour writes are
    // masked: a shader without outputs leaves the attachments undefined otherwise.
    frame.target.bind();
    frame.passes.begin(frame.view, frame.settings);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    frame.drawOwnReflectors(gbuffer.depthProgram());
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  gbuffer.shade(frame.target, frame.passes, frame.view, frame.settings, screen_, options, plan);
  // The counts are the fragment shader's atomics: glGetNamedBufferSubData sees them only
  // behind this barrier (as ssr's).
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return plan.taken;
}

}  // namespace mirage
