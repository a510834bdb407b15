// The reflectors of a frame drawn once as a G-buffer, then shaded by a screen-space pass over
// their pixels: the deferred way to run an expensive reflector shader once per visible pixel
// after a single pass over the reflectors' triangles (on llvmpipe a pass over spheres9's
// reflectors costs about 10 ms whatever its shader, so a depth pre-pass followed by a shading
// pass paid that twice). The G-buffer is the frame target itself — colour (the reflectors at
// their base colour), ids and depth — with an rgba32f texture of normals beside
// (render/shaders/gbuffer.glsl); the shading pass is a reflector shader compiled with
// MIRAGE_REFLECTOR_SCREEN (render/shaders/reflector_screen.glsl) under fullscreen.vert.
#pragma once

#include <vector>

#include "core/camera.h"
#include "core/frame_settings.h"
#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "render/frame_target.h"
#include "render/scene_passes.h"

namespace mirage {

// The pixels of `view` that the box `bounds` can cover, as (x0, y0, x1, y1), x1 and y1 past the
// end, widened to whole 2x2 quads (the differentials read a pixel's quad neighbours); the whole
// view when the box reaches behind the eye. Empty (x0 >= x1) when it is off the screen.
ivec4 screenRectangle(const Bounds3& bounds, const View& view);

class ReflectorGBuffer {
 public:
  ReflectorGBuffer();

  // Binds the frame target with the normals beside, sets `passes` up for the view, and clears
  // the normals (0: nothing of a reflector). What is drawn next writes the G-buffer: the
  // reflectors with reflectorProgram(), anything else with its MIRAGE_GBUFFER program.
  void begin(FrameTarget& target, ScenePasses& passes, const View& view,
             const FrameSettings& settings);
  // Reflectors at their base colour with their normals, materials and ids (base_colour.frag
  // under MIRAGE_GBUFFER).
  const gpu::Program& reflectorProgram() const { return reflector_program_; }
  // The screen-space pass `program` over the pixels of the reflectors `own` (instances; null:
  // every reflector): the normals and the depth bound for gbuffer.glsl, drawn into the target's
  // colour with its alpha (the eye distance) masked; the depth is read, not attached. One draw a
  // reflector, scissored to its bounds' screen rectangle (u_gbuffer_reflector: the pass shades
  // that reflector's pixels only): llvmpipe runs a screen-space shader over every pixel it
  // covers, discarded or not, so a pass over the whole screen cost more than the triangle pass
  // it replaced where the reflectors cover little of it (teapots4).
  void shade(const FrameTarget& target, ScenePasses& passes, const View& view,
             const FrameSettings& settings, const gpu::Program& program,
             const std::vector<int>* own) const;

  const gpu::Texture& normals() const { return normals_; }

 private:
  void fit(const FrameTarget& target);

  gpu::Program reflector_program_;
  ivec2 size_{0};
  GLuint color_id_ = 0, depth_id_ = 0;
  gpu::Texture normals_;
  gpu::Framebuffer with_depth_, shading_;
};

}  // namespace mirage
