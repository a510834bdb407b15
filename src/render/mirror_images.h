// Planar mirrors shown through images made for them from the mirrored eye (the scene
// re-rendered: method `planar`, whose reflector pass this is).
#pragma once

#include <span>
#include <vector>

#include "gpu/program.h"
#include "render/frame_target.h"
#include "render/gpu_scene.h"

namespace mirage {

struct MirrorImage {
  int mirror = -1;                     // the reflector instance
  const FrameTarget* image = nullptr;  // its image from the mirrored eye, frame-sized
};

// Draws every reflector of the scene into the bound target: those in `images` with
// `mirror_program` (render/shaders/mirror_image.frag: the image at the mirror's own pixels),
// the others except `skip` with `base_program` (their base colour). With `only`, just the
// reflectors it lists.
void drawMirrorImages(const GpuScene& gpu, std::span<const MirrorImage> images,
                      const gpu::Program& mirror_program, const gpu::Program& base_program,
                      int skip = -1, const std::vector<int>* only = nullptr);

// The pixels (window coordinates, origin bottom-left, [xy, zw)) that world bounds `b` may cover
// in `view`, a pixel of margin around; the whole image when they reach behind the eye. Mirrored
// images share the screen's pixel grid, so a mirror's rectangle also bounds the pixels its
// image is read at.
ivec4 screenRect(const View& view, const Bounds3& b);

}  // namespace mirage
