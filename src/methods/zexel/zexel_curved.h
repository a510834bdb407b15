// Curved reflectors in method `zexel`: the forward-mapped planar mirror paper's future work,
// a reference map serving a curved mirror through inverse warping. Each reflector that is not
// planar (planarReflectors in scene.h: not flat to 1e-4 of its size at time 0) keeps a
// depth-preserving cube map — colour, and in alpha the distance along the ray from the centre of
// its bounds, as every frame target stores it — of the scene without it, the other reflectors
// in their base colour (order 1, as the planar maps). Per pixel, zexel_inverse.frag searches the
// reflected ray's epipolar line in that map (zexel_inverse_shared.h) and shows the colour where
// the ray first passes behind the stored surface, or the environment.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "methods/method.h"
#include "methods/zexel/zexel_cube_map.h"
#include "methods/zexel/zexel_distance_pyramid.h"
#include "render/probe_array.h"
#include "render/reflector_gbuffer.h"

namespace mirage {

class ZexelCurvedReflectors {
 public:
  // The parameters it reads (`zexel-curved`, `zexel-cube-size`, `zexel-curved-step`,
  // `zexel-curved-bounds`), for the method's entry.
  static std::vector<ParamSpec> params();

  explicit ZexelCurvedReflectors(const MethodSetup& setup);

  // Captures every map the first time (and when the mip setting changed), then again once what
  // it shows drifted beyond the tolerances, within the probe budget (a camera move alone changes
  // nothing here).
  void update(FrameContext& frame);
  // Draws the curved reflectors this frame owns into the frame target (bound again after) and
  // returns them: once into a G-buffer (render/reflector_gbuffer.h), then the search as a
  // screen-space pass over their pixels, one draw a reflector. spheres9's spheres hold 83K
  // triangles over 58K pixels: a search run per triangle ran on quads most of whose lanes were
  // off the triangle. The pass that draws the remaining reflectors in their base colour skips
  // these. Draws nothing (and returns none) at order 0 or with `--zexel-curved base`. The
  // searches add their pixels and reads to the method's counters (MIRAGE_ZEXEL_COUNT_CURVED_*,
  // bound by the caller).
  std::vector<int> draw(FrameContext& frame);
  // `zexel_curved_reflectors` (served by inverse warping), `zexel_cube_captures`, and from the
  // method's counters of the last frame, `zexel_curved_reads_per_ray`.
  void addStats(std::map<std::string, double>& stats, const std::vector<double>& counters) const;

 private:
  bool inverse_;
  int size_;
  ZexelInverseSettings search_;
  std::vector<int> curved_;         // the reflector instances served, in order (cube = index)
  ProbeArray cubes_;                // RGBA32F, one cube per curved reflector
  ZexelDistancePyramid distances_;  // their distances and the search's bounds
  RecapturePolicy recapture_;
  gpu::Program program_, base_program_;
  std::vector<vec3> centres_;  // where each cube was captured
  std::vector<int> diffuse_;   // every diffuse instance
  ReflectorGBuffer gbuffer_;
};

}  // namespace mirage
