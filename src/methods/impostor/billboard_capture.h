// Renders the textures of a BillboardSet and keeps them up to date: a billboard is re-captured
// only when what it shows changed (its object or the reflector it faces moved, so its capture
// camera or the object's transform differ, or the lighting changed) — never for a view change.
#pragma once

#include <memory>
#include <vector>

#include "gpu/framebuffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "methods/impostor/billboard_set.h"
#include "render/gpu_scene.h"
#include "render/scene_passes.h"

namespace mirage {

class BillboardCapture {
 public:
  explicit BillboardCapture(int size);

  // Captures what changed since the last call; returns the number of billboards captured.
  int update(GpuScene& gpu, ScenePasses& passes, const BillboardSet& set,
             const FrameSettings& settings);

  // Colour (diffuse) or normal (reflective) with coverage: RGBA16F, mip-mapped.
  const gpu::Texture& surfaces() const { return surfaces_; }
  // Reflective billboards' surface points, coverage in w (RGBA32F, one level).
  const gpu::Texture& positions() const { return positions_; }
  long captures() const { return captures_; }
  int size() const { return size_; }

 private:
  // What a billboard's texture depends on; equal keys mean an up-to-date texture.
  struct Key {
    CameraDesc camera;
    mat4 object{0.0f};
    uint64_t shape = 0;  // the object's shape version (deforming reflectors)
    // The light, for diffuse billboards (a reflective one holds normals and positions only).
    vec3 light_dir{0.0f}, light_color{0.0f}, ambient{0.0f};
    bool operator==(const Key& o) const;
  };
  Key keyOf(const GpuScene& gpu, const BillboardSpec& b) const;
  void allocate(const BillboardSet& set);
  void capture(GpuScene& gpu, ScenePasses& passes, const BillboardSpec& b,
               const FrameSettings& settings);

  int size_;
  gpu::Texture surfaces_, positions_, depth_;
  gpu::Framebuffer fbo_;
  gpu::Program diffuse_program_, reflector_program_;
  std::vector<Key> keys_;
  std::vector<bool> valid_;
  long captures_ = 0;
};

}  // namespace mirage
