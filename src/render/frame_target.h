// The frame every method renders into: linear RGBA32F radiance (alpha: distance from the eye),
// an R32UI reflector-ID buffer (0 = not a reflector), and depth. Read back top row first.
#pragma once

#include "core/image.h"
#include "gpu/framebuffer.h"
#include "gpu/texture.h"

namespace mirage {

class FrameTarget {
 public:
  explicit FrameTarget(ivec2 size);

  ivec2 size() const { return size_; }
  // Binds the framebuffer and sets the viewport.
  void bind() const;
  // Clears colour to black, IDs to 0 and depth to the far plane.
  void clear() const;

  Image readColor() const;
  IdImage readIds() const;
  // Replaces colour and IDs with images made on the CPU (the ray tracer's output).
  void upload(const Image& color, const IdImage& ids);

  const gpu::Texture& color() const { return color_; }
  const gpu::Texture& ids() const { return ids_; }
  const gpu::Texture& depth() const { return depth_; }

 private:
  ivec2 size_;
  gpu::Texture color_, ids_, depth_;
  gpu::Framebuffer fbo_;
};

}  // namespace mirage
