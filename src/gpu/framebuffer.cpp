#include "gpu/framebuffer.h"

#include <vector>

#include "core/error.h"

namespace mirage::gpu {

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
