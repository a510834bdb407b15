// An impostor method's reflector shader, both ways a frame may run it: as the screen-space pass
// over the reflector G-buffer (render/reflector_gbuffer.h; compiled with
// MIRAGE_REFLECTOR_SCREEN under fullscreen.vert) and as a pass over a reflector's triangles
// (under scene.vert) over the depth the G-buffer pass left. --impostor-pass chooses: auto takes
// the screen pass for a reflector whose triangles are small on the screen (screenPassPays), its
// triangles for one whose triangles are large.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gpu/program.h"
#include "methods/method.h"
#include "render/reflector_gbuffer.h"

namespace mirage {

// --impostor-pass, for the impostor methods' parameters, and its value.
ParamSpec impostorPassParam();
ReflectorPass impostorPass(const ParamValues& params);

// The last frame's reflectors by each pass, as stats: `impostor_screen_reflectors`,
// `impostor_triangle_reflectors`.
void addPassStats(std::map<std::string, double>& stats, const ReflectorPasses& passes);

class ImpostorShader {
 public:
  // `fragment` includes impostor_trace.glsl; `defines` are the method's. The triangle program
  // is compiled unless `pass` is kScreen, the screen one unless it is kTriangles.
  ImpostorShader(const char* fragment, std::vector<std::string> defines, ReflectorPass pass);

  // Sets a uniform on each program compiled.
  template <typename T>
  void set(const char* name, const T& value) const {
    for (const gpu::Program* p : programs()) p->set(name, value);
  }
  std::vector<const gpu::Program*> programs() const;

  // Draws the frame's own reflectors (FrameContext::own) into `gbuffer` at their base colour,
  // then shades their pixels, each reflector the way `pass` chooses: the expensive shader runs
  // once per visible pixel, after one pass over the reflectors' triangles that writes the depth.
  // Ends with the barrier that lets the stage read the trace's counts back.
  ReflectorPasses draw(FrameContext& frame, ReflectorGBuffer& gbuffer) const;

 private:
  ReflectorPass pass_;
  gpu::Program screen_, triangles_;
};

}  // namespace mirage
