// A cube-map array of reflection probes, one cube per probe, kept up to date in a moving scene:
// each probe is re-captured once what it shows has drifted beyond the tolerances of a
// RecapturePolicy, most drifted first, within the policy's budget per frame
// (render/recapture.h). Every method that keeps probes at its reflectors holds one.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "gpu/texture.h"
#include "render/cube_capture.h"
#include "render/recapture.h"

namespace mirage {

class GpuScene;

class ProbeArray {
 public:
  // What the probes hold: `format` texels, faces of `size` texels.
  ProbeArray(int size, GLenum format = GL_RGBA16F);

  // Draws what probe `k` shows into the face whose view is given (the face is bound, cleared).
  using Draw = std::function<void(int k, const View& view)>;

  // Makes room for `count` probes, with a full mip chain when `mip`; forgets every capture when
  // the storage changes (they are then all captured at the next update).
  void allocate(int count, bool mip);
  // How far each probe has drifted: probe k is at centres[k] and shows the instances shown[k].
  std::vector<Drift> drifts(const GpuScene& gpu, const std::vector<vec3>& centres,
                            const std::vector<std::vector<int>>& shown) const;
  // Captures probe k now, between the near and far distances.
  void capture(const GpuScene& gpu, int k, const vec3& centre, const std::vector<int>& shown,
               float near_plane, float far_plane, const Draw& draw);
  // Rebuilds the mip chain if anything was captured since the last call.
  void finish();
  // Ends a frame (the captures' ages count frames).
  void nextFrame() { states_.nextFrame(); }
  // Where probe k was captured; `otherwise` when it has not been.
  vec3 centre(int k, const vec3& otherwise) const;
  // allocate, then capture the probes `policy` picks and finish; returns how many it captured.
  int update(const GpuScene& gpu, int count, bool mip, const std::vector<vec3>& centres,
             const std::vector<std::vector<int>>& shown, const RecapturePolicy& policy,
             float near_plane, float far_plane, const Draw& draw);
  // update with one probe at each instance of `own` (its bounds' centre), showing `shown_from`
  // and every reflector of `reflectors` but its own, between 1e-3 and 100 times `radius` (the
  // size of what the probes show).
  int updateAtReflectors(const GpuScene& gpu, bool mip, const std::vector<int>& own,
                         const std::vector<int>& shown_from, const std::vector<int>& reflectors,
                         const RecapturePolicy& policy, float radius, const Draw& draw);

  const gpu::Texture& texture() const { return texture_; }
  void bind(int unit) const { texture_.bind(unit); }
  int size() const { return size_; }
  long captures() const { return captures_; }
  // Probes beyond the tolerances that the budget left for later frames, at the last update.
  int pending() const { return pending_; }

 private:
  int size_;
  GLenum format_;
  gpu::Texture texture_;
  std::unique_ptr<CubeCapture> cube_;
  ProbeRecapture states_;
  long captures_ = 0;
  int pending_ = 0;
  std::vector<int> captured_since_finish_;  // probes
};

// Diffuse instances plus every reflector but `own`: what a probe at reflector `own` shows.
std::vector<int> shownByProbe(const std::vector<int>& diffuse, const std::vector<int>& reflectors,
                              int own);

}  // namespace mirage
