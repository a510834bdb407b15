// Renders the scene from a point into the six faces of a cube map, or of one cube of a
// cube-map array, with the face orientations that GL's cube-map sampling expects
// (shading/cubemap.h). Used by reflection probes and by every capture of the methods.
#pragma once

#include <functional>

#include "core/camera.h"
#include "gpu/framebuffer.h"
#include "gpu/texture.h"

namespace mirage {

class CubeCapture {
 public:
  // `size` is the face size of the cube maps this capture renders into.
  explicit CubeCapture(int size);

  int size() const { return size_; }
  // The camera of face f (GL order +X, -X, +Y, -Y, +Z, -Z) at `center`.
  static CameraDesc faceCamera(int face, const vec3& center, float near_plane, float far_plane);

  // For each face: binds `target`'s face (layer 6 * cube + face of level 0) with a depth buffer,
  // clears it, and calls draw(view) with the face's view.
  void capture(const gpu::Texture& target, int cube, const vec3& center, float near_plane,
               float far_plane, const std::function<void(const View&)>& draw);

 private:
  int size_;
  gpu::Texture depth_;
  gpu::Framebuffer fbo_;
};

}  // namespace mirage
