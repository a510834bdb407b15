// Captures in moving scenes, amortised: a capture (a billboard, a reflection probe) is redone
// only when what it shows has drifted beyond a tolerance, and at most a budget of them per
// frame, most drifted first. The impostor paper re-captures a billboard only "when needed"; this
// is that rule made measurable, shared by every method that keeps captures between frames.
//
// Drift is measured two ways, each against its own tolerance:
//  - an angle: how far the direction a capture sees something from has turned (a billboard's
//    object seen from its reflector; an object seen from a probe's centre);
//  - texels: how far something moved or grew in the capture's image, in its texels.
// A change neither measure covers (the light's colour, a deforming shape) counts as beyond every
// tolerance. With both tolerances 0 and no budget, every change re-captures: exact.
#pragma once

#include <cstdint>
#include <vector>

#include "core/bounds.h"
#include "core/math.h"

namespace mirage {

class GpuScene;

struct RecapturePolicy {
  float angle_degrees = 0.0f;  // 0: any turn re-captures
  float texels = 0.0f;         // 0: any motion re-captures
  int budget = 0;              // re-captures a frame beyond the captures that must be made; 0: all
};

// How far one capture has drifted from what it would show now.
struct Drift {
  bool invalid =
      false;  // nothing captured yet (or its storage is new): captured whatever the budget
  bool unmeasured = false;  // changed in a way no tolerance covers
  float angle = 0.0f;       // radians
  float texels = 0.0f;
  int age = 0;  // frames since it was captured: breaks ties, oldest first
};

// Which captures to redo this frame, in the order to redo them: every invalid one, then those
// beyond tolerance (an unmeasured change, or drift over either tolerance) by decreasing drift
// relative to its tolerance, at most policy.budget of them (0: all).
std::vector<int> chooseRecaptures(const std::vector<Drift>& drift, const RecapturePolicy& policy);

// What a probe (a cube map rendered from `centre`) showed when it was captured.
struct ProbeState {
  bool valid = false;
  vec3 centre{0.0f};
  std::vector<mat4> matrices;    // the shown instances' transforms
  std::vector<uint64_t> shapes;  // their shape versions
  vec3 light_direction{0.0f}, light_color{0.0f}, ambient{0.0f};
  int frame = 0;  // the frame counter of the capture
};

// What each of a set of probes showed when last captured, and how far each has drifted since
// (render/probe_array.h keeps one for its cubes).
class ProbeRecapture {
 public:
  // How far probe `p`, now at `centre` showing `shown`, has drifted; `face_size` converts its
  // angles to texels (one texel of a cube face spans about 90° / face_size).
  Drift drift(const GpuScene& gpu, int p, const vec3& centre, const std::vector<int>& shown,
              int face_size) const;
  // Records that probe p was captured now.
  void captured(const GpuScene& gpu, int p, const vec3& centre, const std::vector<int>& shown);
  // Forgets every capture (their storage was re-allocated).
  void reset(size_t count) { states_.assign(count, ProbeState{}); }
  size_t size() const { return states_.size(); }
  const ProbeState& state(int p) const { return states_[size_t(p)]; }
  // Ends a frame: ages the captures.
  void nextFrame() { ++frame_; }

 private:
  std::vector<ProbeState> states_;
  int frame_ = 0;
};

// The angle (radians) a point cloud's motion subtends at a viewer: the largest displacement of
// the corners of `local` between `before` and `now` (each relative to its viewer position),
// over the distance from the viewer now to the box `world` (the distance to its nearest face
// when the viewer is inside it).
float motionAngle(const Bounds3& local, const mat4& before, const mat4& now,
                  const vec3& viewer_before, const vec3& viewer_now, const Bounds3& world);

}  // namespace mirage
