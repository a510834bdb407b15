#include "render/cube_capture.h"

#include "core/error.h"

namespace mirage {

CubeCapture::CubeCapture(int size)
    : size_(size), depth_(gpu::Texture::create2D(GL_DEPTH_COMPONENT32F, size, size)) {
  fbo_.attachDepth(depth_);
}

CameraDesc CubeCapture::faceCamera(int face, const vec3& center, float near_plane,
                                   float far_plane) {
  static const vec3 kForward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  static const vec3 kUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                              {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  CameraDesc c;
  c.name = "cube-face";
  c.position = center;
  c.target = center + kForward[face];
  c.up = kUp[face];
  c.fov_y_degrees = 90.0f;
  c.near_plane = near_plane;
  c.far_plane = far_plane;
  return c;
}

void CubeCapture::capture(const gpu::Texture& target, int cube, const vec3& center,
                          float near_plane, float far_plane,
                          const std::function<void(const View&)>& draw) {
  if (target.size().x != size_)
    throwRuntime("cube capture of size {} into a {} cube map", size_, target.size().x);
  const float black[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  for (int face = 0; face < 6; ++face) {
    fbo_.attachColor(0, target, 0, 6 * cube + face);
    fbo_.setDrawBuffers(1);
    fbo_.checkComplete("cube capture");
    fbo_.bind();
    glViewport(0, 0, size_, size_);
    glDepthMask(GL_TRUE);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, black);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far_depth);
    draw(View(faceCamera(face, center, near_plane, far_plane), {size_, size_}));
  }
}

}  // namespace mirage
