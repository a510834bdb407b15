// What the two modes of `mirage compare` share: one view (cmd_compare.cpp) and the frames along
// a camera path (compare_path.cpp).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/display.h"
#include "eval/report.h"
#include "gpu/context.h"
#include "gpu/frame_timer.h"
#include "methods/frame.h"
#include "raytrace/tracer.h"

namespace mirage::app {

// A compare run set up: the scene on the GPU, the methods to run (the reference first) and the
// report's header filled in.
struct CompareRun {
  const Scene* scene = nullptr;
  SceneLayers layers;   // the scene's layers (scene/layers.h), for the per-layer figures
  ivec2 size{0};        // the output: images, metrics
  int ssaa = 1;         // --ssaa: sub-pixels per side
  ivec2 frame_size{0};  // what the methods render at: size * ssaa
  FrameSettings settings;
  DisplaySettings display;
  float heatmap_max = 0.25f;
  std::map<std::string, std::string> params;
  std::vector<std::string> methods;  // methods[0] is the reference
  std::filesystem::path dir;
  gpu::Context* context = nullptr;
  FrameRenderer* renderer = nullptr;         // at frame_size
  FrameRenderer* timing_renderer = nullptr;  // at size, for the times under --ssaa > 1
  std::unique_ptr<RayTracer> tracer;         // error causes and the reference check
  CompareReport report;
};

// The clock a method's frames are timed with: the GPU's for GPU methods, else the wall clock.
gpu::Clock methodClock(const CompareRun& run, const Method& method);
// The report entry of a method without figures or images: name, description, order, stats.
MethodReport describeMethod(const CompareRun& run, const std::string& name, const Method& method);

// The image names of one method (and frame) in the report directory.
struct MapFiles {
  std::string image, error_image, flip_image;
};
// Writes STEM.png (the image), STEM.err.png (absolute error against `reference`, on the run's
// heat-map scale) and STEM.flip.png (the FLIP map, on the fixed scale 0..1).
MapFiles writeMaps(const CompareRun& run, const std::string& stem, const Image& shown,
                   const Image& reference, const Image2D<float>& flip);

// Renders `frames` frames along the path of `camera` (equal steps from its first key's time to its
// last's), every method in turn on each frame, and fills `run.report` with per-frame metrics.
// Under --ssaa the frames are timed again at the output size; `check_spp` > 0 checks the
// reference of the first frame against a converged one.
void comparePath(CompareRun& run, const CameraDesc& camera, int frames, int check_spp);

}  // namespace mirage::app
