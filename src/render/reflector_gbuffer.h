// The reflectors of a frame drawn once as a G-buffer, then shaded by a screen-space pass over
// their pixels: the deferred way to run an expensive reflector shader once per visible pixel
// after a single pass over the reflectors' triangles (on llvmpipe a pass over spheres9's
// reflectors costs about 10 ms whatever its shader, so a depth pre-pass followed by a shading
// pass paid that twice). The G-buffer is the frame target itself — colour (the reflectors at
// their base colour), ids and depth — with an rgba32f texture of normals beside
// (render/shaders/gbuffer.glsl); the shading pass is a reflector shader compiled with
// MIRAGE_REFLECTOR_SCREEN (render/shaders/reflector_screen.glsl) under fullscreen.vert.
#pragma once

#include <functional>
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

// How a reflector's pixels are shaded after the G-buffer pass (--impostor-pass).
enum class ReflectorPass { kAuto, kScreen, kTriangles };

// Whether a reflector of `triangles` triangles whose bounds cover `rectangle` (screenRectangle)
// is shaded more cheaply by the screen-space pass than by its triangles: where its triangles
// are small (under kScreenPassPixelsPerTriangle pixels of the rectangle each) the triangle pass
// runs the expensive shader on 2x2 quads and 4x4 blocks most of whose pixels are off the
// triangle; where they are large, the screen pass pays for the rectangle's pixels off the
// reflector. Measured on llvmpipe (docs/benchmarks.md, "Scale"): spheres9's spheres cover about
// 1 pixel a triangle, teapots4's teapots about 40.
constexpr double kScreenPassPixelsPerTriangle = 8.0;
bool screenPassPays(size_t triangles, const ivec4& rectangle);

struct ShadeOptions {
  const std::vector<int>* own = nullptr;  // the reflectors shaded (null: every one)
  // Called with a reflector's instance before its draw: for that reflector's uniforms.
  std::function<void(int instance)> each;
  const gpu::Program* triangles = nullptr;  // the shader over the triangles; null: screen only
  ReflectorPass pass = ReflectorPass::kAuto;
};

// How many reflectors a frame shaded each way.
struct ReflectorPasses {
  int screen = 0, triangles = 0;
};

// The way each of the scene's reflectors (by index in Scene::reflectorInstances) is shaded: its
// scissor rectangle in `screen` or in `triangles`, empty in the other (both: not drawn).
struct ReflectorPlan {
  std::vector<ivec4> screen, triangles;
  ReflectorPasses taken;
};

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
  // The reflectors' depth alone (depth_only.frag): the pre-pass when no reflector takes the
  // screen pass.
  const gpu::Program& depthProgram() const { return depth_program_; }
  // Which way each reflector of `options.own` (instances; null: every reflector) goes: the
  // screen-space pass, or with `options.triangles` its triangles — for ReflectorPass::kAuto
  // where they are large on the screen (screenPassPays).
  ReflectorPlan plan(const GpuScene& gpu, const View& view, const ShadeOptions& options) const;
  // Shades the pixels of the planned reflectors. The screen-space pass `program`: the normals
  // and the depth bound for gbuffer.glsl, drawn into the target's colour with its alpha (the
  // eye distance) masked; the depth is read, not attached. One draw a reflector, scissored to
  // its bounds' screen rectangle (u_gbuffer_reflector: the pass shades that reflector's pixels
  // only): llvmpipe runs a screen-space shader over every pixel it covers, discarded or not.
  // `options.triangles`: the same shader over a reflector's triangles, under scene.vert, into
  // the target over the depth drawn before (GL_LEQUAL: its visible pixels only).
  void shade(const FrameTarget& target, ScenePasses& passes, const View& view,
             const FrameSettings& settings, const gpu::Program& program,
             const ShadeOptions& options, const ReflectorPlan& plan) const;
  // Every reflector of `options.own` by the screen-space pass `program`.
  void shade(const FrameTarget& target, ScenePasses& passes, const View& view,
             const FrameSettings& settings, const gpu::Program& program,
             const ShadeOptions& options) const;

  const gpu::Texture& normals() const { return normals_; }

 private:
  void fit(const FrameTarget& target);
  // The reflectors whose rectangle (by index in the scene's reflectors) is not empty, by the
  // screen-space pass and by their triangles.
  void drawScreen(const FrameTarget& target, ScenePasses& passes, const View& view,
                  const FrameSettings& settings, const gpu::Program& program,
                  const ShadeOptions& options, const std::vector<ivec4>& rectangles) const;
  static void drawTriangles(const FrameTarget& target, ScenePasses& passes, const View& view,
                            const FrameSettings& settings, const gpu::Program& program,
                            const ShadeOptions& options, const std::vector<ivec4>& rectangles);

  gpu::Program reflector_program_, depth_program_;
  ivec2 size_{0};
  GLuint color_id_ = 0, depth_id_ = 0;
  gpu::Texture normals_;
  gpu::Framebuffer with_depth_, shading_;
};

}  // namespace mirage
