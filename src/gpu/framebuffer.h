// Framebuffer objects (DSA): colour and depth attachments, completeness checks.
#pragma once

#include "gpu/handle.h"
#include "gpu/texture.h"

namespace mirage::gpu {

// The largest side of a frame the current context can render into: the least of its texture,
// renderbuffer, framebuffer and viewport limits.
int maxFrameSide();

class Framebuffer {
 public:
  Framebuffer();

  GLuint id() const { return handle_.id(); }
  // Attaches a level of `texture`; layer >= 0 selects one layer (or cube face) of it.
  void attachColor(int index, const Texture& texture, int level = 0, int layer = -1);
  void attachDepth(const Texture& texture, int level = 0, int layer = -1);
  // Selects colour attachments 0..count-1 as draw buffers.
  void setDrawBuffers(int count);
  // Throws RuntimeError naming `what` if the framebuffer is incomplete.
  void checkComplete(const char* what) const;
  void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }

 private:
  void attach(GLenum attachment, const Texture& texture, int level, int layer);
  Handle<FramebufferTraits> handle_;
};

}  // namespace mirage::gpu
