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

  // Moves the scene to `time`: uploads changed instance transforms and the vertices of deforming
  // meshes, and moves the light.
  void setTime(float time);
  // Increments whenever an instance transform or shape, the light or the environment changes, so
  // that methods re-capture only when something did.
  uint64_t version() const { return version_; }
  // Finer versions for methods that redo only what a change touches: an instance's increments
  // when its transform or its shape changes, its shape version when its mesh deforms, the
  // light's when the light moves or changes colour.
  uint64_t instanceVersion(int instance) const { return instance_versions_[size_t(instance)]; }
  uint64_t transformVersion(int instance) const { return transform_versions_[size_t(instance)]; }
  uint64_t shapeVersion(int instance) const { return shape_versions_[size_t(instance)]; }
  // The versions of everything a probe at a reflector (drawn without that reflector) can show:
  // the light, the `diffuse` instances it draws, every reflector's transform and, when there are
  // two or more reflectors (which see one another), every reflector's shape. A lone rippling
  // mirror thus changes no probe of its own.
  std::vector<uint64_t> probeKey(const std::vector<int>& diffuse) const;
  uint64_t lightVersion() const { return light_version_; }
  // The light at time().
  const Light& light() const { return light_; }
  // The instance's mesh at time() in object space: its deformed copy when it deforms.
  const Mesh& mesh(int instance) const;
  const mat4& instanceMatrix(int instance) const { return matrices_[size_t(instance)]; }
  const std::vector<mat4>& instanceMatrices() const { return matrices_; }
  // World bounds of an instance at time() (Scene::instanceBounds, its object-space bounds kept
  // from construction), and of every instance together (Scene::bounds at time()).
  Bounds3 instanceBounds(int instance) const;
  Bounds3 bounds() const;
  // The object-space vertex positions the instance is drawn with, read back from its vertex
  // buffer on the GPU (tests check what was uploaded).
  std::vector<vec3> uploadedPositions(int instance) const;

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
  void uploadVertices(int mesh_index, const Mesh& mesh);

  const Scene& scene_;
  const EnvironmentMap& environment_map_;
  std::vector<GpuMesh> meshes_;
  std::vector<gpu::Texture> textures_;
  gpu::Texture environment_;
  gpu::Buffer instance_buffer_, material_buffer_;
  std::vector<mat4> matrices_;
  std::vector<Bounds3> local_bounds_;  // per instance: Scene::localBounds, read once
  std::vector<Mesh> deformed_;  // per instance: the mesh at time_ (empty unless it deforms)
  std::vector<uint64_t> instance_versions_, transform_versions_, shape_versions_;
  std::vector<int> reflectors_;
  Light light_;
  float time_ = -1.0f;
  uint64_t version_ = 0, light_version_ = 0;
};

}  // namespace mirage
