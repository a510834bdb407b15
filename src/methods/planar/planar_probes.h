// `planar --planar-curved probes`: a probe captured at the centre of each reflector that is not
// planar, showing the direct part and the other reflectors at their base colour, for the curved
// reflectors that planar's mirrored views see (a composite's default: method mixed).
#pragma once

#include <memory>
#include <vector>

#include "methods/method.h"
#include "render/cube_capture.h"

namespace mirage {

class PlanarProbes {
 public:
  PlanarProbes(const Scene& scene, const std::vector<int>& planar, int size);

  // Captures the probes again when what they show changed (or the mip setting did).
  void update(FrameContext& frame, const gpu::Program& base_program);
  // Draws the curved reflectors through their probes into the bound target, for the view whose
  // passes are begun.
  void draw(const FrameContext& frame) const;
  long captures() const { return captures_; }

 private:
  std::vector<int> curved_;   // the reflectors that are not planar
  std::vector<int> diffuse_;  // what the probes show besides reflectors
  int size_;
  size_t reflectors_;  // cube-array layers: one cube per reflector id - 1
  gpu::Program program_;
  gpu::Texture probes_;
  std::unique_ptr<CubeCapture> cube_;
  std::vector<uint64_t> key_;
  bool captured_ = false, mip_ = false;
  long captures_ = 0;
};

}  // namespace mirage
