// The default stage of a bare mesh file: the model fitted to 2 units on the ground, mirror-
// finished when the file has no materials, a checkerboard floor, things to reflect, a camera that
// sees the model, and a mirror sphere when the model itself reflects nothing.
#include <zlib.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene/mesh_stage.h"
#include "scene/scene_loader.h"
#include "support/scenes.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

TEST(MeshStage, PlyModelIsMirrorFinishedOnACheckerGround) {
  fs::path dir = testTempDir("mesh-stage");
  std::ofstream(dir / "block.ply") << boxPlyText({1, 2, 3}, {5, 4, 4});  // extent 4 x 2 x 1
  Scene s = loadScene((dir / "block.ply").string());
  EXPECT_EQ(s.name, "block");

  int model = instanceNamed(s, "block");
  ASSERT_GE(model, 0);
  const Material& finish = s.materials[size_t(s.instances[size_t(model)].material)];
  EXPECT_TRUE(finish.isReflector());
  EXPECT_EQ(finish.albedo, vec3(0.05f));
  // Fitted: largest extent 2, standing on y = 0, centred in x and z.
  Bounds3 b = s.instanceBounds(model);
  EXPECT_NEAR(b.extent().x, kStageModelSize, 1e-5f);
  EXPECT_NEAR(b.extent().y, 1.0f, 1e-5f);
  EXPECT_NEAR(b.extent().z, 0.5f, 1e-5f);
  EXPECT_NEAR(b.lo.y, 0.0f, 1e-5f);
  EXPECT_NEAR(b.center().x, 0.0f, 1e-5f);
  EXPECT_NEAR(b.center().z, 0.0f, 1e-5f);

  int floor = instanceNamed(s, "floor");
  ASSERT_GE(floor, 0);
  const Material& checker = s.materials[size_t(s.instances[size_t(floor)].material)];
  EXPECT_GT(checker.checker_scale, 0.0f);
  EXPECT_NEAR(s.instanceBounds(floor).hi.y, 0.0f, 1e-6f);

  // The model reflects, so no extra mirror; diffuse boxes stand around it without touching it.
  EXPECT_EQ(s.reflectorInstances(), std::vector<int>{model});
  int boxes = 0;
  for (size_t i = 0; i < s.instances.size(); ++i) {
    if (int(i) == model || int(i) == floor) continue;
    EXPECT_FALSE(s.isReflector(int(i)));
    Bounds3 o = s.instanceBounds(int(i));
    bool apart = o.lo.x > 1.0f || o.hi.x < -1.0f || o.lo.z > 1.0f || o.hi.z < -1.0f;
    EXPECT_TRUE(apart) << s.instances[i].name << " overlaps the model's footprint";
    ++boxes;
  }
  EXPECT_GE(boxes, 3);

  // One camera, front-left and above, that sees the model's centre.
  ASSERT_EQ(s.cameras.size(), 1u);
  const CameraDesc& cam = s.cameras[0];
  EXPECT_LT(cam.position.x, 0.0f);
  EXPECT_GT(cam.position.z, 0.0f);
  EXPECT_GT(cam.position.y, kStageModelSize);
  View view(cam, {720, 512});
  vec3 p = view.project(b.center());
  EXPECT_GT(p.x, 0.0f);
  EXPECT_LT(p.x, 720.0f);
  EXPECT_GT(p.y, 0.0f);
  EXPECT_LT(p.y, 512.0f);
  EXPECT_TRUE(s.environment.image.empty());  // the procedural sky
}

TEST(MeshStage, GzippedPlyIsNamedWithoutBothExtensions) {
  fs::path dir = testTempDir("mesh-stage");
  std::string text = boxPlyText({0, 0, 0}, {1, 3, 1});
  gzFile f = gzopen((dir / "tower.ply.gz").c_str(), "wb");
  ASSERT_NE(f, nullptr);
  gzwrite(f, text.data(), unsigned(text.size()));
  gzclose(f);
  Scene s = makeMeshStage((dir / "tower.ply.gz").string());
  EXPECT_EQ(s.name, "tower");
  int model = instanceNamed(s, "tower");
  ASSERT_GE(model, 0);
  EXPECT_NEAR(s.instanceBounds(model).extent().y, kStageModelSize, 1e-5f);
}

TEST(MeshStage, DiffuseModelGetsAMirrorSphereBesideIt) {
  fs::path dir = testTempDir("mesh-stage");
  std::ofstream(dir / "clay.mtl") << "newmtl clay\nKd 0.8 0.6 0.4\n";
  std::ofstream(dir / "clay.obj") << "mtllib clay.mtl\nusemtl clay\n"
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                     "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  Scene s = makeMeshStage((dir / "clay.obj").string());
  int sphere = instanceNamed(s, "mirror-sphere");
  ASSERT_GE(sphere, 0);
  EXPECT_EQ(s.reflectorInstances(), std::vector<int>{sphere});
  // Beside the model, on the ground, not inside it.
  Bounds3 b = s.instanceBounds(sphere);
  EXPECT_NEAR(b.lo.y, 0.0f, 1e-3f);
  EXPECT_GT(b.lo.x, 1.0f);
}

TEST(MeshStage, BadFilesAreInputErrors) {
  fs::path dir = testTempDir("mesh-stage");
  try {
    makeMeshStage((dir / "missing.ply").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.ply: no such file"), std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "broken.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n";
  try {
    makeMeshStage((dir / "broken.ply").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.ply"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mirage::test
