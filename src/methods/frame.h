// One scene ready to render on the GPU at a fixed image size: environment, GPU scene, shared
// passes and the frame target. Renders frames with any method and reads them back.
#pragma once

#include <memory>

#include "methods/method.h"
#include "scene/environment.h"

namespace mirage {

struct RenderedFrame {
  Image color;  // linear radiance; alpha is the distance from the eye
  IdImage ids;  // reflector id per pixel (0 = none)
};

// The frame reduced by --ssaa n (core/supersample.h): colour box-filtered in linear radiance,
// ids by majority. n = 1 returns it unchanged.
RenderedFrame downsample(RenderedFrame frame, int n);

class FrameRenderer {
 public:
  // Needs a current OpenGL 4.5 context.
  FrameRenderer(const Scene& scene, ivec2 size);

  const Scene& scene() const { return scene_; }
  ivec2 size() const { return target_.size(); }
  GpuScene& gpu() { return *gpu_; }
  ScenePasses& passes() { return *passes_; }
  FrameTarget& target() { return target_; }
  const EnvironmentMap& environment() const { return environment_; }

  // Creates a method for this scene; `given` holds parameter values by name (other methods'
  // parameters are ignored).
  std::unique_ptr<Method> createMethod(const std::string& name,
                                       const std::map<std::string, std::string>& given,
                                       const FrameSettings& settings);

  // Moves the scene to `time`, updates the method and renders one frame of `view`. With
  // `counts`, also what the frame did (methods/method.h: frameCounts), from the method's stats
  // before and after it: asked for only where it is shown (bench, the viewer), since a method's
  // stats may read counters back from the GPU.
  void render(Method& method, const View& view, float time, const FrameSettings& settings,
              gpu::FrameTimer* timer = nullptr, std::map<std::string, double>* counts = nullptr);
  RenderedFrame read() const;

 private:
  const Scene& scene_;
  EnvironmentMap environment_;
  std::unique_ptr<GpuScene> gpu_;
  std::unique_ptr<ScenePasses> passes_;
  FrameTarget target_;
};

}  // namespace mirage
