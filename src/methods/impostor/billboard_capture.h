// Renders the textures of a BillboardSet and keeps them up to date in a moving scene. A
// billboard's texture is an image of its object seen from one direction: while the object and
// the reflector it faces move, the old image stays right as long as that direction, in the
// object's own frame, has turned less than a tolerance (render/recapture.h). Until then the
// billboard keeps the quad it was captured with, carried along by its object's motion (a
// reflective billboard's surface points with it), and only the billboards that drifted beyond
// the tolerances are re-captured, most drifted first, within a budget per frame. Never for a
// view change.
#pragma once

#include <memory>
#include <vector>

#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/impostor/billboard_set.h"
#include "render/gpu_scene.h"
#include "render/recapture.h"
#include "render/scene_passes.h"

namespace mirage {

class BillboardCapture {
 public:
  explicit BillboardCapture(int size);

  // Re-captures what drifted beyond `policy` (everything, the first time) and moves every
  // billboard of `set` not captured now to where its old capture stands (its quad, surface
  // points and normals carried by its object's motion). `others`: the drifts of captures the
  // caller keeps under the same policy and budget (the stage's environment); `others_due`
  // receives whether each is to be captured now. Returns the number of billboards captured.
  int update(GpuScene& gpu, ScenePasses& passes, BillboardSet& set, const FrameSettings& settings,
             const RecapturePolicy& policy, const std::vector<Drift>& others = {},
             std::vector<bool>* others_due = nullptr);

  // Colour (diffuse) or normal (reflective) with coverage: RGBA16F, mip-mapped.
  const gpu::Texture& surfaces() const { return surfaces_; }
  // Reflective billboards' surface points, coverage in w (RGBA32F, one level).
  const gpu::Texture& positions() const { return positions_; }
  long captures() const { return captures_; }
  int size() const { return size_; }
  // Billboards beyond the tolerances that the budget left for later frames, at the last update.
  int pending() const { return pending_; }
  // The largest drift (degrees) of a billboard shown from an old capture, at the last update.
  float largestDriftDegrees() const { return largest_drift_; }

 private:
  // What a billboard showed when it was captured.
  struct Captured {
    bool valid = false;
    vec3 corner{0.0f}, edge_u{0.0f}, edge_v{0.0f};
    vec3 seen_from{0.0f};  // object space, unit: from the object towards the capture camera
    mat4 object{1.0f};
    uint64_t shape = 0;
    vec3 light_dir{0.0f}, light_color{0.0f}, ambient{0.0f};
    int frame = 0;
  };
  Captured capturedNow(const GpuScene& gpu, const BillboardSpec& b) const;
  Drift drift(const GpuScene& gpu, const BillboardSpec& b, const Captured& c) const;
  void allocate(const BillboardSet& set);
  void capture(GpuScene& gpu, ScenePasses& passes, const BillboardSpec& b,
               const FrameSettings& settings);

  int size_;
  gpu::Texture surfaces_, positions_, depth_;
  gpu::Framebuffer fbo_;
  gpu::Program diffuse_program_, reflector_program_;
  std::vector<Captured> captured_;
  long captures_ = 0;
  int frame_ = 0, pending_ = 0;
  float largest_drift_ = 0.0f;
};

}  // namespace mirage
