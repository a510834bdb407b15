// Renders the depth maps of a set of DepthMapSpecs (colour + GL depth, the object alone through
// its camera) and builds their SRDMs, keeping each up to date by key: the depth and the SRDMs
// depend only on the camera in the object's space and the settings, so rigid motion rebuilds
// nothing; the colour depends on the light as the object sees it (its direction in the object's
// space, colour, ambient), so a light change — or a rotation relative to the light — re-captures
// the colour alone. A reflector's map of itself holds its object-space normal instead, which
// nothing but its depth's changes invalidate. The SRDMs are built on the CPU from the depth read
// back (the default: the faster here), or on the GPU straight from the depth array by
// SrdmGpuBuilder (greedy only).
#pragma once

#include <memory>
#include <vector>

#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/depthmap/depthmap_set.h"
#include "methods/depthmap/srdm.h"
#include "methods/depthmap/srdm_gpu_builder.h"
#include "render/gpu_scene.h"
#include "render/recapture.h"
#include "render/scene_passes.h"

namespace mirage {

enum class SrdmBuilder { kCpu, kGpu };

class DepthMapCapture {
 public:
  // Needs a current OpenGL 4.5 context. Throws InputError for settings out of range, and for
  // the GPU builder with a simplifier other than greedy.
  DepthMapCapture(const DepthMapOptions& options, const SrdmSettings& srdm,
                  SrdmBuilder builder = SrdmBuilder::kCpu);

  // Captures and builds what changed: a map whose depth no longer fits (a new spec, a new shape)
  // at once, a colour map once the light turned beyond `policy`'s angle, within its budget.
  // Returns the number of colour captures made.
  int update(GpuScene& gpu, ScenePasses& passes, const std::vector<DepthMapSpec>& specs,
             const FrameSettings& settings, const RecapturePolicy& policy);

  // RGBA16F, premultiplied, mip-mapped: colour, or a reflector's object-space normal.
  const gpu::Texture& colors() const { return colors_; }
  const gpu::Texture& depths() const { return depths_; }  // DEPTH_COMPONENT32F
  const gpu::Texture& srdms() const { return srdms_; }    // RGBA32F, maps x n layers

  long colorCaptures() const { return color_captures_; }
  // Colour maps beyond the tolerance that the budget left for later frames.
  int pending() const { return pending_; }
  long depthCaptures() const { return depth_captures_; }
  long srdmBuilds() const { return srdm_builds_; }
  // The last build's wall time; the GPU builder's includes waiting for it.
  double lastBuildMs() const { return last_build_ms_; }
  int droppedSamples() const;

 private:
  struct ColorKey {
    vec3 light_dir{0.0f}, light_color{0.0f}, ambient{0.0f};
    bool operator==(const ColorKey&) const = default;
  };
  void allocate(int maps);
  void render(GpuScene& gpu, ScenePasses& passes, const DepthMapSpec& spec, int layer,
              bool with_depth, const FrameSettings& settings);
  void build(int layer, const View& view);

  DepthMapOptions options_;
  SrdmSettings srdm_settings_;
  gpu::Texture colors_, depths_, srdms_, scratch_depth_;
  gpu::Framebuffer fbo_;
  gpu::Program program_, normal_program_;
  std::vector<ColorKey> color_keys_;
  int pending_ = 0;
  std::vector<bool> color_valid_, depth_valid_;
  std::vector<DepthMapSpec> built_for_;
  std::vector<uint64_t> built_shape_;  // the object's shape version at the depth map's build
  std::unique_ptr<SrdmGpuBuilder> gpu_builder_;  // null: the CPU builder
  std::vector<int> dropped_;                     // per map
  long color_captures_ = 0, depth_captures_ = 0, srdm_builds_ = 0;
  double last_build_ms_ = 0.0;
};

}  // namespace mirage
