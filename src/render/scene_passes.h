// The rasterisation passes every method shares: the frame uniforms for a view, the environment
// background, the diffuse objects (the shared view-independent shading) and the reflectors with
// whatever reflector program a method supplies.
#pragma once

#include <functional>
#include <span>

#include "core/camera.h"
#include "core/frame_settings.h"
#include "gpu/buffer.h"
#include "gpu/program.h"
#include "render/gpu_scene.h"
#include "shading/gpu_types.h"

namespace mirage {

shading::FrameData makeFrameData(const View& view, const Scene& scene, float time,
                                 const FrameSettings& settings, float env_max_lod);

class ScenePasses {
 public:
  explicit ScenePasses(GpuScene& scene);

  GpuScene& scene() { return scene_; }
  // Uploads the frame uniforms of `view`, binds shared buffers, sets the GL state. Call first.
  void begin(const View& view, const FrameSettings& settings);
  const shading::FrameData& frameData() const { return frame_; }

  // The environment seen directly (level 0, as the ray tracer samples it).
  void drawBackground() const;
  // One triangle over the viewport with `program` (fullscreen.vert), without the depth test: a
  // screen-space pass.
  void drawFullscreen(const gpu::Program& program) const;
  // All diffuse instances except `exclude`.
  void drawDiffuse(int exclude = -1) const;
  // The same with another program (a G-buffer pass).
  void drawDiffuseWith(const gpu::Program& program, int exclude = -1) const;
  // The given diffuse instances only.
  void drawDiffuseInstances(std::span<const int> instances) const;
  // All reflector instances except `exclude`, with a method's reflector program.
  void drawReflectors(const gpu::Program& program, int exclude = -1) const;
  // The given reflector instances only, in the order given.
  void drawReflectorInstances(const gpu::Program& program, std::span<const int> instances) const;
  // Background and diffuse objects: the direct part of a frame.
  void drawDirect() const {
    drawBackground();
    drawDiffuse();
  }

 private:
  GpuScene& scene_;
  gpu::Program background_, diffuse_;
  gpu::Buffer frame_buffer_;
  shading::FrameData frame_{};
  gpu::Handle<gpu::VertexArrayTraits> empty_vao_;
};

}  // namespace mirage
