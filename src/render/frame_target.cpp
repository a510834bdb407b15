#include "render/frame_target.h"

namespace mirage {

FrameTarget::FrameTarget(ivec2 size) : size_(size) {
  color_ = gpu::Texture::create2D(GL_RGBA32F, size.x, size.y);
  ids_ = gpu::Texture::create2D(GL_R32UI, size.x, size.y);
  ids_.setFilter(GL_NEAREST, GL_NEAREST);
  depth_ = gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
  fbo_.attachColor(0, color_);
  fbo_.attachColor(1, ids_);
  fbo_.attachDepth(depth_);
  fbo_.setDrawBuffers(2);
  fbo_.checkComplete("frame");
}

void FrameTarget::bind() const {
  fbo_.bind();
  glViewport(0, 0, size_.x, size_.y);
}

void FrameTarget::clear() const {
  const float black[4] = {0, 0, 0, 0};
  const GLuint zero[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, black);
  glClearNamedFramebufferuiv(fbo_.id(), GL_COLOR, 1, zero);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far_depth);
}

Image FrameTarget::readColor() const {
  Image image(size_.x, size_.y);
  glGetTextureImage(color_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(image.pixelCount() * sizeof(vec4)),
                    image.data());
  image.flipVertically();
  return image;
}

IdImage FrameTarget::readIds() const {
  IdImage image(size_.x, size_.y);
  glGetTextureImage(ids_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    GLsizei(image.pixelCount() * sizeof(uint32_t)), image.data());
  image.flipVertically();
  return image;
}

void FrameTarget::upload(const Image& color, const IdImage& ids) {
  Image c = color;
  IdImage i = ids;
  c.flipVertically();
  i.flipVertically();
  color_.upload(0, GL_RGBA, GL_FLOAT, c.data());
  ids_.upload(0, GL_RED_INTEGER, GL_UNSIGNED_INT, i.data());
}

}  // namespace mirage
