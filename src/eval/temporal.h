// The temporal error of a method along a camera path (docs/reports.md, "Temporal error"): how much
// its error against the reference changes from one frame to the next on reflector pixels — what
// a viewer sees as flicker and popping, which a mean of per-frame errors does not show (a
// constant error does not flicker; one that jumps between two frames does).
//
// For frame f ≥ 1, over the pixels that are reflector pixels of the reference in both frames
// f − 1 and f: the mean over pixels and colour channels of |e_f − e_{f−1}|, e = method − reference
// (display values in [0, 1]). The figure is the mean over the frames f ≥ 1. Fed the reference
// and a black frame, it is the reference's own frame-to-frame change, the scale to read a
// method's against (the reflection itself moving).
#pragma once

#include <vector>

#include "core/image.h"

namespace mirage {

class TemporalError {
 public:
  // The next frame: the method's display image, the reference's and the reference's reflector
  // ids (0: not a reflector pixel). Every frame of one size.
  void add(const Image& method, const Image& reference, const IdImage& reference_ids);
  // Each frame's change (NaN for the first, and for a frame without a reflector pixel in common
  // with the one before).
  const std::vector<double>& perFrame() const { return per_frame_; }
  // The mean over the frames that have one; NaN when none has.
  double mean() const;

 private:
  Image previous_error_;
  IdImage previous_ids_;
  std::vector<double> per_frame_;
};

}  // namespace mirage
