// loadModel's dispatch by extension, loadMesh's merging, isModelFile.
#include <gtest/gtest.h>

#include "scene/gltf_test_files.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"
#include "scene/ply_test_writer.h"

namespace mirage {
namespace {

using test::expectInputError;
using test::TempDir;

TEST(ModelLoader, KnowsModelExtensions) {
  for (const char* p : {"a.ply", "a.PLY", "dir.v2/a.ply.gz", "a.Ply.GZ", "a.obj", "a.gltf", "a.glb",
                        "a.stl", "a.fbx", "a.dae", "a.3ds", "a.off"})
    EXPECT_TRUE(isModelFile(p)) << p;
  for (const char* p : {"scene.json", "a.png", "a.exr", "a.obj.gz", "a.gz", "README", "a.txt", ""})
    EXPECT_FALSE(isModelFile(p)) << p;
}

TEST(ModelLoader, DispatchesByExtension) {
  TempDir dir;
  std::string cube = test::writePly(test::cubeElements(), "binary_little_endian");
  for (const char* name : {"cube.ply", "CUBE.PLY"}) {
    LoadedModel m = loadModel(dir.write(name, cube));
    ASSERT_EQ(m.meshes.size(), 1u);
    EXPECT_EQ(m.meshes[0].triangleCount(), 12u);
    EXPECT_EQ(m.mesh_material, (std::vector<int>{-1}));
    EXPECT_EQ(m.mesh_transform, (std::vector<mat4>{mat4(1.0f)}));
    EXPECT_TRUE(m.materials.empty());
  }
  EXPECT_EQ(loadModel(dir.write("cube.ply.gz", test::gzip(cube))).meshes[0].triangleCount(), 12u);
  std::string obj = dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(loadModel(obj).meshes[0].triangleCount(), 1u);
}

TEST(ModelLoader, ErrorsNameTheFile) {
  TempDir dir;
  std::string missing = dir.file("missing.ply");
  expectInputError([&] { loadModel(missing); }, {missing, "no such file"});
  std::string txt = dir.write("notes.txt", "hello");
  expectInputError([&] { loadModel(txt); }, {txt, "unsupported model file extension '.txt'"});
  expectInputError([&] { loadModel(dir.file("")); }, {"folder"});
  std::string nan = dir.write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n");
  // tinyobjloader may read "nan" as NaN or as 0; a NaN must not get through.
  try {
    LoadedModel m = loadModel(nan);
    for (const vec3& p : m.meshes[0].positions) EXPECT_TRUE(isFinite(p));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(nan), std::string::npos) << e.what();
  }
}

TEST(ModelLoader, LoadMeshMergesNodesWithTheirTransforms) {
  TempDir dir;
  test::QuadScene s = test::quadScene(dir);
  std::string path = test::writeGltf(dir, s);
  LoadedModel model = loadModel(path);
  Mesh merged = loadMesh(path);
  EXPECT_EQ(merged.name, "quad");
  EXPECT_EQ(merged.source, path);
  ASSERT_EQ(merged.vertexCount(), 12u);
  ASSERT_EQ(merged.triangleCount(), 6u);
  EXPECT_EQ(merged.uvs.size(), 12u);
  // The second quad's corner (1,0,0) placed by the node matrix (translation 10, 20, 30).
  EXPECT_EQ(merged.positions[4 + 1], vec3(11, 20, 30));
  EXPECT_EQ(merged.triangles[2], uvec3(4, 5, 6));
  // The first quad's corner rotated and scaled under the translated root.
  EXPECT_NEAR(glm::distance(merged.positions[1], vec3(1, 2, 1)), 0.0f, 1e-5f);
  // Normals follow: +Z turned 90 degrees about +Y is +X.
  EXPECT_NEAR(glm::distance(merged.normals[0], vec3(1, 0, 0)), 0.0f, 1e-5f);
  merged.validate();
  Bounds3 b;
  for (size_t i = 0; i < model.meshes.size(); ++i)
    b.extend(model.meshes[i].bounds().transformed(model.mesh_transform[i]));
  EXPECT_NEAR(glm::distance(merged.bounds().lo, b.lo), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(merged.bounds().hi, b.hi), 0.0f, 1e-5f);
}

TEST(ModelLoader, LoadMeshDropsAttributesSomeMeshesLack) {
  TempDir dir;
  // Two OBJ groups: one with texture coordinates, one without.
  std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
      "o a\nf 1/1 2/2 3/3\no b\nf 1 3 2\n";
  Mesh m = loadMesh(dir.write("mixed.obj", obj));
  EXPECT_EQ(m.vertexCount(), 6u);
  EXPECT_EQ(m.triangleCount(), 2u);
  EXPECT_TRUE(m.uvs.empty());
  EXPECT_EQ(m.triangles[1], uvec3(3, 4, 5));
  EXPECT_EQ(m.name, "mixed");
}

}  // namespace
}  // namespace mirage
