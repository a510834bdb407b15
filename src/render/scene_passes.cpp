#include "render/scene_passes.h"

#include "gpu/feedback_check.h"

namespace mirage {

shading::FrameData makeFrameData(const View& view, const Scene& scene, float time,
                                 const FrameSettings& settings, float env_max_lod) {
  shading::FrameData f{};
  f.view_proj = view.viewProjection();
  f.inv_view_proj = glm::inverse(f.view_proj);
  f.eye = vec4(view.eye(), time);
  const Light light = scene.lightAt(time);
  f.light_dir = vec4(glm::normalize(light.direction), 0.0f);
  f.light_color = vec4(light.color, 0.0f);
  f.ambient = vec4(light.ambient, 0.0f);
  f.viewport = vec4(float(view.size().x), float(view.size().y), view.tanHalfFovY(), env_max_lod);
  f.options = ivec4(settings.order, settings.mip ? 1 : 0, 0, 0);
  f.env = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  return f;
}

ScenePasses::ScenePasses(GpuScene& scene)
    : scene_(scene),
      background_(gpu::Program::graphics("render/shaders/fullscreen.vert",
                                         "render/shaders/background.frag")),
      diffuse_(gpu::Program::graphics("render/shaders/scene.vert", "render/shaders/diffuse.frag")),
      frame_buffer_(sizeof(shading::FrameData)),
      empty_vao_(gpu::createVertexArray()) {}

void ScenePasses::begin(const View& view, const FrameSettings& settings) {
  frame_ = makeFrameData(view, scene_.scene(), scene_.time(), settings,
                         float(scene_.environment().levels() - 1));
  frame_buffer_.uploadValue(frame_);
  frame_buffer_.bindBase(GL_UNIFORM_BUFFER, MIRAGE_BIND_FRAME);
  scene_.bindShared();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
}

void ScenePasses::drawBackground() const {
  drawFullscreen(background_);
}

void ScenePasses::drawFullscreen(const gpu::Program& program) const {
  program.use();
  glDepthMask(GL_FALSE);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(empty_vao_.id());
  gpu::checkFeedback();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
}

void ScenePasses::drawDiffuse(int exclude) const {
  drawDiffuseWith(diffuse_, exclude);
}

void ScenePasses::drawDiffuseWith(const gpu::Program& program, int exclude) const {
  program.use();
  const Scene& s = scene_.scene();
  for (int i = 0; i < int(s.instances.size()); ++i)
    if (i != exclude && !s.isReflector(i)) scene_.draw(i);
}

void ScenePasses::drawDiffuseInstances(std::span<const int> instances) const {
  diffuse_.use();
  for (int i : instances) scene_.draw(i);
}

void ScenePasses::drawReflectors(const gpu::Program& program, int exclude) const {
  program.use();
  const Scene& s = scene_.scene();
  for (int i = 0; i < int(s.instances.size()); ++i)
    if (i != exclude && s.isReflector(i)) scene_.draw(i);
}

void ScenePasses::drawReflectorInstances(const gpu::Program& program,
                                         std::span<const int> instances) const {
  program.use();
  for (int i : instances) scene_.draw(i);
}

}  // namespace mirage
