#include "render/gpu_scene.h"

#include <cstddef>

#include "core/check.h"
#include "gpu/feedback_check.h"
#include "shading/gpu_types.h"

namespace mirage {

namespace {

struct Vertex {
  vec3 position;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
};
static_assert(sizeof(Vertex) == 48, "vertex layout");

std::vector<Vertex> vertexData(const Mesh& mesh) {
  std::vector<Vertex> vertices(mesh.positions.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    vertices[i].position = mesh.positions[i];
    vertices[i].normal = i < mesh.normals.size() ? mesh.normals[i] : vec3(0, 1, 0);
    vertices[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : vec2(0.0f);
    vertices[i].tangent = i < mesh.tangents.size() ? mesh.tangents[i] : vec4(1, 0, 0, 1);
  }
  return vertices;
}

}  // namespace

GpuScene::GpuScene(const Scene& scene, const EnvironmentMap& environment)
    : scene_(scene), environment_map_(environment) {
  for (const Mesh& mesh : scene.meshes) {
    const std::vector<Vertex> vertices = vertexData(mesh);
    GpuMesh g;
    g.vertices = gpu::Buffer::fromSpan<Vertex>(vertices);
    g.indices = gpu::Buffer::fromSpan<uvec3>(mesh.triangles);
    g.index_count = GLsizei(mesh.triangles.size() * 3);
    g.vao = gpu::createVertexArray();
    const GLuint vao = g.vao.id();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, g.indices.id());
    const GLuint offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal),
                              offsetof(Vertex, uv), offsetof(Vertex, tangent)};
    const GLint sizes[] = {3, 3, 2, 4};
    for (GLuint a = 0; a < 4; ++a) {
      glEnableVertexArrayAttrib(vao, a);
      glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
      glVertexArrayAttribBinding(vao, a, 0);
    }
    meshes_.push_back(std::move(g));
  }

  for (const TextureImage& t : scene.textures) {
    int levels = gpu::Texture::fullMipLevels(std::max(t.image.width(), t.image.height()));
    gpu::Texture tex =
        gpu::Texture::create2D(GL_RGBA16F, t.image.width(), t.image.height(), levels);
    // Texture coordinates put (0, 0) at the image's bottom-left (GL's convention, and the ray
    // tracer's); images are stored top row first, and GL takes the first row as t = 0.
    Image rows = t.image;
    rows.flipVertically();
    tex.upload(0, GL_RGBA, GL_FLOAT, rows.data());
    tex.generateMipmaps();
    tex.setWrap(GL_REPEAT);
    textures_.push_back(std::move(tex));
  }

  int size = environment.faceSize();
  environment_ = gpu::Texture::createCube(GL_RGBA16F, size, gpu::Texture::fullMipLevels(size));
  for (int f = 0; f < 6; ++f)
    environment_.uploadLayer(0, f, GL_RGBA, GL_FLOAT, environment.face(f).data());
  environment_.generateMipmaps();
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  std::vector<shading::MaterialData> materials;
  for (const Material& m : scene.materials) materials.push_back(m.gpuData());
  material_buffer_ = gpu::Buffer::fromSpan<shading::MaterialData>(materials);
  matrices_.assign(scene.instances.size(), mat4(1.0f));
  for (int i = 0; i < int(scene.instances.size()); ++i)
    local_bounds_.push_back(scene.localBounds(i));
  deformed_.resize(scene.instances.size());
  instance_versions_.assign(scene.instances.size(), 0);
  transform_versions_.assign(scene.instances.size(), 0);
  reflectors_ = scene.reflectorInstances();
  shape_versions_.assign(scene.instances.size(), 0);
  setTime(0.0f);
}

void GpuScene::setTime(float time) {
  if (time == time_) return;
  const bool first = time_ < 0.0f;
  bool moved = false, changed = false;
  for (size_t i = 0; i < scene_.instances.size(); ++i) {
    const Instance& inst = scene_.instances[i];
    const mat4 m = inst.matrixAt(time);
    bool touched = false;
    if (m != matrices_[i] || first) {
      moved = touched = true;
      matrices_[i] = m;
      ++transform_versions_[i];
    }
    // A deformation that travels (speed != 0) changes the shape at every new time.
    if (inst.deforms() && (first || inst.deformation.period() > 0.0f)) {
      scene_.meshAt(int(i), time, deformed_[i]);
      uploadVertices(inst.mesh, deformed_[i]);
      ++shape_versions_[i];
      changed = touched = true;
    }
    if (touched) ++instance_versions_[i];
  }
  const Light light = scene_.lightAt(time);
  if (first || light.direction != light_.direction || light.color != light_.color ||
      light.ambient != light_.ambient) {
    light_ = light;
    ++light_version_;
    changed = true;
  }
  time_ = time;
  if (moved) uploadInstances();
  if (moved || changed) ++version_;
}

void GpuScene::uploadVertices(int mesh_index, const Mesh& mesh) {
  const std::vector<Vertex> vertices = vertexData(mesh);
  meshes_[size_t(mesh_index)].vertices.upload(std::span<const Vertex>(vertices));
}

std::vector<uint64_t> GpuScene::probeKey(const std::vector<int>& diffuse) const {
  std::vector<uint64_t> key = {light_version_};
  for (int i : diffuse) key.push_back(instance_versions_[size_t(i)]);
  for (int r : reflectors_) key.push_back(transform_versions_[size_t(r)]);
  if (reflectors_.size() >= 2)
    for (int r : reflectors_) key.push_back(shape_versions_[size_t(r)]);
  return key;
}

std::vector<vec3> GpuScene::uploadedPositions(int instance) const {
  const Mesh& m = mesh(instance);
  std::vector<Vertex> vertices(m.positions.size());
  meshes_[size_t(scene_.instances[size_t(instance)].mesh)].vertices.download(
      vertices.data(), vertices.size() * sizeof(Vertex));
  std::vector<vec3> positions;
  for (const Vertex& v : vertices) positions.push_back(v.position);
  return positions;
}

const Mesh& GpuScene::mesh(int instance) const {
  MIRAGE_CHECK(instance >= 0 && size_t(instance) < scene_.instances.size());
  const Instance& inst = scene_.instances[size_t(instance)];
  return inst.deforms() ? deformed_[size_t(instance)] : scene_.meshes[size_t(inst.mesh)];
}

void GpuScene::uploadInstances() {
  std::vector<shading::InstanceData> data(scene_.instances.size());
  std::vector<int> reflectors = scene_.reflectorInstances();
  for (size_t i = 0; i < data.size(); ++i) {
    const Instance& inst = scene_.instances[i];
    data[i].model = matrices_[i];
    data[i].normal_matrix = mat4(normalMatrix(matrices_[i]));
    auto it = std::find(reflectors.begin(), reflectors.end(), int(i));
    int reflector_id = it == reflectors.end() ? 0 : int(it - reflectors.begin()) + 1;
    data[i].ids = ivec4(inst.material, reflector_id, inst.mesh, 0);
  }
  instance_buffer_.upload(std::span<const shading::InstanceData>(data));
}

Bounds3 GpuScene::instanceBounds(int instance) const {
  return local_bounds_[size_t(instance)].transformed(matrices_[size_t(instance)]);
}

Bounds3 GpuScene::bounds() const {
  Bounds3 b;
  for (int i = 0; i < int(matrices_.size()); ++i) b.extend(instanceBounds(i));
  return b;
}

void GpuScene::bindShared() const {
  instance_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_INSTANCES);
  material_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_MATERIALS);
  environment_.bind(MIRAGE_UNIT_ENVIRONMENT);
}

void GpuScene::draw(int instance) const {
  const Instance& inst = scene_.instances[size_t(instance)];
  const Material& material = scene_.materials[size_t(inst.material)];
  if (material.albedo_texture >= 0)
    textures_[size_t(material.albedo_texture)].bind(MIRAGE_UNIT_ALBEDO);
  if (material.normal_map >= 0) textures_[size_t(material.normal_map)].bind(MIRAGE_UNIT_NORMAL_MAP);
  glUniform1i(0, instance);  // layout(location = 0) uniform int u_instance
  const GpuMesh& mesh = meshes_[size_t(inst.mesh)];
  glBindVertexArray(mesh.vao.id());
  gpu::checkFeedback();
  glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
}

}  // namespace mirage
