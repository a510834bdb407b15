#include "gpu/framebuffer.h"

#include <algorithm>

#include <vector>

#include "core/error.h"

namespace mirage::gpu {

int maxFrameSide() {
  GLint texture = 0, renderbuffer = 0, width = 0, height = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &width);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &height);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  return std::min({texture, renderbuffer, width, height, viewport[0], viewport[1]});
}

Framebuffer::Framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  handle_ = Handle<FramebufferTraits>(id);
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int level, int layer) {
  if (layer >= 0)
    glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
  else
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::attachColor(int index, const Texture& texture, int level, int layer) {
  attach(GLenum(GL_COLOR_ATTACHMENT0 + index), texture, level, layer);
}

void Framebuffer::attachDepth(const Texture& texture, int level, int layer) {
  attach(GL_DEPTH_ATTACHMENT, texture, level, layer);
}

void Framebuffer::setDrawBuffers(int count) {
  std::vector<GLenum> buffers;
  for (int i = 0; i < count; ++i) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  glNamedFramebufferDrawBuffers(id(), GLsizei(buffers.size()), buffers.data());
}

void Framebuffer::checkComplete(const char* what) const {
  GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throwRuntime("{} framebuffer is incomplete (status 0x{:x})", what, status);
}

}  // namespace mirage::gpu
