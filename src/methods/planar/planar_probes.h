// `planar --planar-curved probes`: a probe captured at the centre of each reflector that is not
// planar, showing the direct part and the other reflectors at their base colour, for the curved
// reflectors that planar's mirrored views see (a composite's default: method mixed).
#pragma once

#include <memory>
#include <vector>

#include "methods/method.h"
#include "render/probe_array.h"

namespace mirage {

class PlanarProbes {
 public:
  PlanarProbes(const Scene& scene, const std::vector<int>& planar, int size,
               const RecapturePolicy& recapture);

  // Captures the probes again once what they show drifted beyond the tolerances (all of them
  // the first time, or when the mip setting changed).
  void update(FrameContext& frame, const gpu::Program& base_program);
  // Draws the curved reflectors through their probes into the bound target, for the view whose
  // passes are begun.
  void draw(const FrameContext& frame) const;
  long captures() const { return probes_.captures(); }
  int pending() const { return probes_.pending(); }

 private:
  std::vector<int> curved_;   // the reflectors that are not planar
  std::vector<int> diffuse_;  // what the probes show besides reflectors
  ProbeArray probes_;         // one cube per curved reflector, in the order of curved_
  RecapturePolicy recapture_;
  gpu::Program program_;
};

}  // namespace mirage
