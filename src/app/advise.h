// `mirage advise` (docs/advise.md): measures every candidate technique on every reflector over
// calibration views — its error against the ray tracer under matched supersampling, and the
// frame time it adds, all in one run — then picks the assignment with the least reflector error
// within a frame budget (app/advise_choice.h) and measures that composite.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/display.h"
#include "core/frame_settings.h"
#include "scene/scene.h"

namespace mirage::app {

// --budget: milliseconds, or a multiple of the `none` frame's median ("4x").
struct Budget {
  double value = 4.0;
  bool relative = true;
  double ms(double none_ms) const { return relative ? value * none_ms : value; }
};
// Throws InputError naming --budget when `text` is neither.
Budget parseBudget(const std::string& text);

// The most entries (distinct candidates) a chosen assignment has: the choice is exact among
// those (app/advise_choice.h).
inline constexpr int kMaxAdviseEntries = 3;

// A method with parameter values: one point of a method's grid.
struct Candidate {
  std::string method;
  std::map<std::string, std::string> params;  // "order" sets its K
  std::string label;                          // "depthmap:srdm-m=16"
};

// The grid of `methods` (assignable methods): each with its defaults, and its main parameters
// at a cheaper and a dearer value.
std::vector<Candidate> candidateGrid(const std::vector<std::string>& methods);

struct CalibrationView {
  CameraDesc camera;  // at `time`
  float time = 0.0f;
  std::string label;  // "main", "walk@2.67s"
};

// The scene's cameras (each at `time`), and `along` views spread over the first camera path.
std::vector<CalibrationView> calibrationViews(const Scene& scene, float time, int along);

struct AdviseSetup {
  ivec2 size{360, 256};  // output pixels; costs are timed at this size
  int ssaa = 4;          // quality is measured at size * ssaa against the same samples' reference
  int frames = 5;        // timed frames per view and assignment
  FrameSettings settings;
  DisplaySettings display;
  std::map<std::string, std::string> params;  // method parameters given for every candidate
  std::vector<Candidate> candidates;
  std::vector<CalibrationView> views;
  Budget budget;
};

// What one candidate does on one reflector.
struct Measured {
  double sse = 0.0;      // summed over the reflector's pixels in every view (display values)
  double part_ms = 0.0;  // its part of the frame (median), drawing this reflector alone
};

// A candidate that could not be measured: the method failed (an error of its own, or it fell
// back to another on this driver), with what it said.
struct FailedCandidate {
  std::string label;
  std::string reason;
};

struct Advice {
  std::vector<std::string> reflectors;  // instance names, in scene order
  std::vector<size_t> pixels;           // each reflector's pixels over all views
  std::vector<Candidate> candidates;    // those measured: every list below is indexed by them
  std::vector<FailedCandidate> failed;  // the others, left out of the choice
  std::vector<std::vector<Measured>> measured;  // [reflector][candidate]
  double none_ms = 0.0;                         // the `none` frame's median
  double base_ms = 0.0;  // a composite's frame without its parts: update, direct part, overhead
  std::vector<double> single_ms;   // each candidate drawing every reflector (median)
  std::vector<double> single_sse;  // its summed error over every reflector
  // Each candidate's entry overhead, paid once per entry: from its parts timed one reflector at a
  // time against its single-method frame.
  std::vector<double> fixed_ms;
  double budget_ms = 0.0;
  bool fits = false;
  std::vector<int> chosen;  // the candidate of each reflector (the cheapest when nothing fits)
  std::vector<ReflectionRule> rules;  // the chosen assignment
  double predicted_ms = 0.0, predicted_sse = 0.0;
  double measured_ms = 0.0, measured_sse = 0.0;
  size_t totalPixels() const;
  double psnr(double sse) const;  // over every reflector pixel of every view
};

// Measures, chooses and measures the choice; a candidate that fails is reported in
// Advice::failed and left out, and only when every candidate fails is that an error
// (RuntimeError). Needs a current OpenGL context.
Advice advise(const Scene& scene, const AdviseSetup& setup);

}  // namespace mirage::app
