// The glTF reader on files the test writes: .gltf with a base64 buffer, .glb, node transforms,
// materials (metallic 1 + roughness 0 = reflector), textures, index types, strides, modes.
#include <gtest/gtest.h>

#include "scene/gltf_test_files.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"

namespace mirage {
namespace {

using nlohmann::json;
using test::QuadScene;
using test::quadScene;
using test::TempDir;
using test::writeGltf;

void expectQuadModel(const LoadedModel& m) {
  ASSERT_EQ(m.meshes.size(), 3u);
  EXPECT_EQ(m.meshes[0].name, "quad");
  EXPECT_EQ(m.mesh_material, (std::vector<int>{0, 0, 1}));
  for (const Mesh& mesh : m.meshes) {
    ASSERT_EQ(mesh.vertexCount(), 4u);
    ASSERT_EQ(mesh.triangleCount(), 2u);
    EXPECT_EQ(mesh.triangles[1], uvec3(0, 2, 3));
    EXPECT_EQ(mesh.normals[2], vec3(0, 0, 1));
    // v flipped to mirage's bottom-left origin: the top-left corner (0, 1, 0) has uv (0, 1).
    ASSERT_EQ(mesh.uvs.size(), 4u);
    EXPECT_EQ(mesh.uvs[3], vec2(0, 1));
    EXPECT_EQ(mesh.uvs[1], vec2(1, 0));
  }
  // root T(1,2,3) * child R(90 deg about +Y) S(2): (1,0,0) -> (2,0,0) -> (0,0,-2) -> (1,2,1).
  vec3 a = transformPoint(m.mesh_transform[0], vec3(1, 0, 0));
  EXPECT_NEAR(glm::distance(a, vec3(1, 2, 1)), 0.0f, 1e-5f) << a.x << " " << a.y << " " << a.z;
  EXPECT_EQ(transformPoint(m.mesh_transform[1], vec3(1, 0, 0)), vec3(11, 20, 30));
  EXPECT_EQ(m.mesh_transform[2], mat4(1.0f));

  ASSERT_EQ(m.materials.size(), 2u);
  const Material& chrome = m.materials[0];
  EXPECT_TRUE(chrome.isReflector());
  EXPECT_NEAR(glm::distance(chrome.tint, vec3(0.9f, 0.8f, 0.7f)), 0.0f, 1e-6f);
  EXPECT_EQ(chrome.albedo, vec3(0.05f));
  const Material& paint = m.materials[1];
  EXPECT_FALSE(paint.isReflector());
  ASSERT_EQ(m.textures.size(), 2u);
  ASSERT_EQ(paint.albedo_texture, 0);
  ASSERT_EQ(paint.normal_map, 1);
  EXPECT_TRUE(m.textures[0].srgb);
  EXPECT_FALSE(m.textures[1].srgb);
  // The albedo PNG holds 128/255 (sRGB) in red; the normal map the same byte, linear.
  EXPECT_NEAR(m.textures[0].image(1, 1).x, srgbToLinear(128.0f / 255.0f), 1e-5f);
  EXPECT_NEAR(m.textures[1].image(1, 1).x, 128.0f / 255.0f, 1e-5f);
  // The painted mesh has a normal map, so it got tangents along +u = +X.
  ASSERT_EQ(m.meshes[2].tangents.size(), 4u);
  EXPECT_NEAR(glm::distance(vec3(m.meshes[2].tangents[0]), vec3(1, 0, 0)), 0.0f, 1e-5f);
}

TEST(GltfReader, ReadsEmbeddedBuffersNodesMaterialsAndTextures) {
  TempDir dir;
  QuadScene s = quadScene(dir);
  std::string path = writeGltf(dir, s);
  LoadedModel m = loadGltf(path);
  expectQuadModel(m);
  EXPECT_EQ(m.meshes[0].source, path);
  expectQuadModel(loadModel(path));
}

TEST(GltfReader, ReadsGlb) {
  TempDir dir;
  QuadScene s = quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}}};  // the BIN chunk
  std::string path = dir.write("quad.glb", test::glb(s.doc, s.buffer.data()));
  expectQuadModel(loadGltf(path));
  expectQuadModel(loadModel(path));
}

TEST(GltfReader, ReadsEveryIndexTypeAndNoIndices) {
  TempDir dir;
  for (int type : {5121, 5123, 5125}) {
    QuadScene s = quadScene(dir, type);
    expectQuadModel(loadGltf(writeGltf(dir, s, fmt::format("i{}.gltf", type))));
  }
  // Without indices: every three vertices make a triangle.
  QuadScene s = quadScene(dir);
  s.doc["meshes"][0]["primitives"][0].erase("indices");
  s.doc["meshes"][1]["primitives"][0].erase("indices");
  for (int a : {0, 1, 2}) s.doc["accessors"][a]["count"] = 3;
  LoadedModel m = loadGltf(writeGltf(dir, s));
  ASSERT_EQ(m.meshes[0].triangleCount(), 1u);
  EXPECT_EQ(m.meshes[0].triangles[0], uvec3(0, 1, 2));
}

TEST(GltfReader, ReadsInterleavedStridedAttributes) {
  TempDir dir;
  QuadScene s = quadScene(dir);
  // Positions and normals interleaved in one view with a 24-byte stride.
  test::GltfBuffer b;
  std::vector<float> inter;
  for (int v = 0; v < 4; ++v) {
    float x = float(v == 1 || v == 2), y = float(v >= 2);
    inter.insert(inter.end(), {x, y, 0, 0, 0, 1});
  }
  size_t base = b.add(inter);
  size_t t = b.add(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});
  size_t i = b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3});
  s.buffer = b;
  s.doc["bufferViews"] = {
      {{"buffer", 0}, {"byteOffset", base}, {"byteLength", 96}, {"byteStride", 24}},
      {{"buffer", 0}, {"byteOffset", i}, {"byteLength", 12}},
      {{"buffer", 0}, {"byteOffset", t}, {"byteLength", 32}}};
  s.doc["accessors"][0]["byteOffset"] = 0;
  s.doc["accessors"][1]["byteOffset"] = 12;
  s.doc["accessors"][2] = {
      {"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}};
  expectQuadModel(loadGltf(writeGltf(dir, s)));
}

TEST(GltfReader, ConvertsStripsAndFansAndSkipsPoints) {
  TempDir dir;
  QuadScene s = quadScene(dir);
  json prim = s.doc["meshes"][0]["primitives"][0];
  json strip = prim, fan = prim, points = prim;
  strip["mode"] = 5;
  fan["mode"] = 6;
  points["mode"] = 0;
  strip.erase("indices");  // 0 1 2 3 as a strip
  fan.erase("indices");
  s.doc["meshes"][0]["primitives"] = {strip, points, fan};
  LoadedModel m = loadGltf(writeGltf(dir, s));
  ASSERT_EQ(m.meshes.size(), 5u);  // two per placed quad (the points are skipped), one painted
  EXPECT_EQ(m.meshes[0].triangles, (std::vector<uvec3>{{0, 1, 2}, {2, 1, 3}}));
  EXPECT_EQ(m.meshes[1].triangles, (std::vector<uvec3>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(GltfReader, DefaultMaterialsAreDiffuse) {
  TempDir dir;
  QuadScene s = quadScene(dir);
  s.doc["materials"][0]["pbrMetallicRoughness"] = json::object();  // metallic 1, roughness 1
  s.doc["meshes"][1]["primitives"][0].erase("material");
  LoadedModel m = loadGltf(writeGltf(dir, s));
  EXPECT_FALSE(m.materials[0].isReflector());
  EXPECT_EQ(m.materials[0].albedo, vec3(1.0f));
  EXPECT_EQ(m.mesh_material[2], -1);
  EXPECT_TRUE(m.meshes[2].tangents.empty());  // no material, no normal map, no tangents
}

TEST(GltfReader, AssimpReadsTheSameGlb) {
  // The Draco fallback goes through assimp: its result must match tinygltf's, uv convention
  // and transforms included.
  TempDir dir;
  QuadScene s = quadScene(dir);
  s.doc["buffers"] = {{{"byteLength", s.buffer.data().size()}}};
  std::string path = dir.write("quad.glb", test::glb(s.doc, s.buffer.data()));
  LoadedModel a = loadWithAssimp(path), g = loadGltf(path);
  ASSERT_EQ(a.meshes.size(), g.meshes.size());
  for (size_t k = 0; k < a.meshes.size(); ++k) {
    SCOPED_TRACE(k);
    const Mesh& am = a.meshes[k];
    const Mesh& gm = g.meshes[k];
    ASSERT_EQ(am.triangleCount(), gm.triangleCount());
    ASSERT_EQ(am.uvs.size(), am.vertexCount());
    for (size_t i = 0; i < am.vertexCount(); ++i) {
      vec3 wa = transformPoint(a.mesh_transform[k], am.positions[i]);
      size_t j = 0;
      while (j < gm.vertexCount() &&
             glm::distance(transformPoint(g.mesh_transform[k], gm.positions[j]), wa) > 1e-5f)
        ++j;
      ASSERT_LT(j, gm.vertexCount()) << "assimp vertex " << i << " has no tinygltf twin";
      EXPECT_NEAR(glm::distance(am.uvs[i], gm.uvs[j]), 0.0f, 1e-6f);
    }
  }
  ASSERT_EQ(a.materials.size(), 2u);
  EXPECT_TRUE(a.materials[0].isReflector());
  EXPECT_NEAR(glm::distance(a.materials[0].tint, vec3(0.9f, 0.8f, 0.7f)), 0.0f, 1e-6f);
  ASSERT_GE(a.materials[1].albedo_texture, 0);
  EXPECT_NEAR(a.textures[size_t(a.materials[1].albedo_texture)].image(0, 0).x,
              srgbToLinear(128.0f / 255.0f), 1e-5f);
}

TEST(GltfReader, KeepsTangentsConsistentWithTheFlippedUvs) {
  // A conformant exporter writes (1, 0, 0, +1) for this quad (u along +X, image up along +Y);
  // after the v flip, mirage's own tangents from the uvs must agree, w included.
  TempDir dir;
  QuadScene s = quadScene(dir);
  size_t t = s.buffer.add(std::vector<float>{1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1});
  s.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", t}, {"byteLength", 64}});
  s.doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}});
  s.doc["meshes"][1]["primitives"][0]["attributes"]["TANGENT"] = 4;
  LoadedModel m = loadGltf(writeGltf(dir, s));
  const Mesh& painted = m.meshes[2];
  ASSERT_EQ(painted.tangents.size(), 4u);
  Mesh recomputed = painted;
  recomputed.computeTangents();
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(painted.tangents[i], vec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(painted.tangents[i], recomputed.tangents[i]), 0.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace mirage
