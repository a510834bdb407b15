#include "render/reflector_gbuffer.h"

#include "shading/gpu_types.h"

namespace mirage {

ReflectorGBuffer::ReflectorGBuffer()
    : reflector_program_(gpu::Program::graphics(
          "render/shaders/scene.vert", "render/shaders/base_colour.frag", {"MIRAGE_GBUFFER 1"})) {}

void ReflectorGBuffer::fit(const FrameTarget& target) {
  const ivec2 size = target.size();
  if (size == size_ && color_id_ == target.color().id() && depth_id_ == target.depth().id()) return;
  size_ = size;
  color_id_ = target.color().id();
  depth_id_ = target.depth().id();
  // Full floats: the passes reflect about this normal, and z, w hold whole numbers.
  normals_ = gpu::Texture::create2D(GL_RGBA32F, size.x, size.y);
  normals_.setFilter(GL_NEAREST, GL_NEAREST);
  with_depth_ = gpu::Framebuffer();
  with_depth_.attachColor(0, target.color());
  with_depth_.attachColor(1, target.ids());
  with_depth_.attachColor(2, normals_);
  with_depth_.attachDepth(target.depth());
  with_depth_.setDrawBuffers(3);
  with_depth_.checkComplete("reflector G-buffer");
  shading_ = gpu::Framebuffer();
  shading_.attachColor(0, target.color());
  shading_.setDrawBuffers(1);
  shading_.checkComplete("reflector G-buffer shading");
}

void ReflectorGBuffer::begin(FrameTarget& target, ScenePasses& passes, const View& view,
                             const FrameSettings& settings) {
  fit(target);
  with_depth_.bind();
  passes.begin(view, settings);
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(with_depth_.id(), GL_COLOR, 2, zero);
}

void ReflectorGBuffer::shade(const FrameTarget& target, ScenePasses& passes, const View& view,
                             const FrameSettings& settings, const gpu::Program& program) const {
  shading_.bind();
  passes.begin(view, settings);
  normals_.bind(MIRAGE_UNIT_GBUFFER_NORMAL);
  target.depth().bind(MIRAGE_UNIT_GBUFFER_DEPTH);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  passes.drawFullscreen(program);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace mirage
