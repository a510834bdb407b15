// What a planar mirror's pixels show this frame, from the cells its warp left: the resolve
// (zexel_resolve.comp: the blend of the splats covering each pixel of the mirror's rectangle),
// before the mirror is drawn (whose shader fills the exposures among its visible pixels).
#pragma once

#include "gpu/program.h"
#include "methods/zexel/zexel_warp_pass.h"

namespace mirage {

class ZexelResolvePass {
 public:
  // Programs for splats of `sizes` (ZexelSplatOptions::splat and unit).
  explicit ZexelResolvePass(const ZexelSplatOptions& sizes);

  // Resolves `target`'s cells for `splats`' rectangle.
  void run(const ZexelSplatOptions& splats, ZexelWarpTarget& target) const;

  // Pixels of a row of `width` an invocation of the resolve handles: a strip of at most 16 where
  // splats reach one pixel (its sliding window of cells), the strips of a row as even as they
  // can be (a work group's 8 strips side by side: none idle but in the last group); else one.
  int strip(int width) const;

 private:
  bool window_;
  gpu::Program resolve_;
};

}  // namespace mirage
