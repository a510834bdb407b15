// The viewer's output pass: the method's frame through the display transform into the window
// and, when the ground truth is on, the reference beside it (a split at a movable line) or in
// its place (flip), and the error heat map of the two (shading/heatmap.h, the reports' colours);
// plus the PSNR of the frame on the reference's reflector pixels.
#pragma once

#include "core/choices.h"
#include "core/display.h"
#include "gpu/handle.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/frame.h"
#include "viewer/truth_renderer.h"

namespace mirage {

enum class TruthMode { kOff = 0, kSplit = 1, kFlip = 2 };
inline constexpr Choice<TruthMode> kTruthModes[] = {
    {"off", TruthMode::kOff}, {"split", TruthMode::kSplit}, {"flip", TruthMode::kFlip}};
const char* truthModeName(TruthMode mode);

struct OutputSettings {
  DisplaySettings display;
  TruthMode truth = TruthMode::kOff;
  // The error against the reference where the method shows (the reference is rendered for it
  // even when `truth` is off).
  bool heatmap = false;
  float heat_max = 0.25f;  // the error drawn as the brightest colour
  float split = 0.5f;      // the split line, a fraction of the width
  int ssaa = 1;            // the frame's sub-pixels per window pixel along each side (--ssaa)
};

class ViewerOutput {
 public:
  ViewerOutput();

  // Puts the reference on the GPU (its rows flipped to GL's bottom-up order).
  void setTruth(const TruthImage& truth);
  void clearTruth() { has_truth_ = false; }
  bool hasTruth() const { return has_truth_; }

  // Draws `frame` into the bound framebuffer, `size` pixels (the frame: size * settings.ssaa,
  // box-filtered in linear radiance before the display transform).
  void draw(const gpu::Texture& frame, ivec2 size, const OutputSettings& settings) const;

 private:
  gpu::Program plain_, with_truth_;
  gpu::Handle<gpu::VertexArrayTraits> vao_;
  gpu::Texture truth_;
  bool has_truth_ = false;
};

// The frame's PSNR (dB, +inf when equal) against the reference on the reference's reflector
// pixels, the frame box-filtered down to the reference's size in linear radiance first; NaN when
// the reference shows no reflector.
double truthPsnr(const RenderedFrame& frame, const TruthImage& truth,
                 const DisplaySettings& display);

}  // namespace mirage
