// The scene on the GPU: one vertex/index buffer pair per mesh, the instance and material
// storage buffers of shading/gpu_types.h, the textures and the environment cube map. Every
// method draws through it, so all of them see the same geometry and the same shading data.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/handle.h"
#include "gpu/texture.h"
#include "scene/environment.h"
#include "scene/scene.h"

namespace mirage {

class GpuScene {
 public:
  GpuScene(const Scene& scene, const EnvironmentMap& environment);
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  const Scene& scene() const { return scene_; }
  const EnvironmentMap& environmentMap() const { return environment_map_; }
  const gpu::Texture& environment() const { return environment_; }
  float time() const { return time_; }

  // Moves the scene to `time` and uploads changed instance transforms.
  void setTime(float time);
  // Increments whenever an instance transform, the light or the environment changes, so that
  // methods re-capture only when something did.
  uint64_t version() const { return version_; }
  const mat4& instanceMatrix(int instance) const { return matrices_[size_t(instance)]; }
  const std::vector<mat4>& instanceMatrices() const { return matrices_; }
  Bounds3 instanceBounds(int instance) const;

  // Binds the instance/material buffers and the environment for any scene program.
  void bindShared() const;
  // Draws one instance with the bound program (binds its textures and sets u_instance).
  void draw(int instance) const;

 private:
  struct GpuMesh {
    gpu::Buffer vertices, indices;
    gpu::Handle<gpu::VertexArrayTraits> vao;
    GLsizei index_count = 0;
  };

  void uploadInstances();

  const Scene& scene_;
  const EnvironmentMap& environment_map_;
  std::vector<GpuMesh> meshes_;
  std::vector<gpu::Texture> textures_;
  gpu::Texture environment_;
  gpu::Buffer instance_buffer_, material_buffer_;
  std::vector<mat4> matrices_;
  float time_ = -1.0f;
  uint64_t version_ = 0;
};

}  // namespace mirage
