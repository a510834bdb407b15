// Formats read through assimp (STL, OFF here): geometry, no materials, errors naming the file.
#include <gtest/gtest.h>

#include "scene/model_loader.h"
#include "scene/model_loader_files.h"

namespace mirage {
namespace {

using test::expectInputError;
using test::TempDir;

// A tetrahedron with outward faces, as ASCII STL.
std::string tetraStl() {
  const vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string s = "solid tetra\n";
  for (const auto& f : faces) {
    vec3 n = glm::normalize(glm::cross(p[f[1]] - p[f[0]], p[f[2]] - p[f[0]]));
    s += fmt::format("facet normal {} {} {}\n outer loop\n", n.x, n.y, n.z);
    for (int k : f) s += fmt::format("  vertex {} {} {}\n", p[k].x, p[k].y, p[k].z);
    s += " endloop\nendfacet\n";
  }
  return s + "endsolid tetra\n";
}

TEST(AssimpReader, ReadsAsciiStl) {
  TempDir dir;
  std::string path = dir.write("tetra.stl", tetraStl());
  for (const LoadedModel& m : {loadWithAssimp(path), loadModel(path)}) {
    ASSERT_EQ(m.meshes.size(), 1u);
    const Mesh& mesh = m.meshes[0];
    EXPECT_EQ(mesh.triangleCount(), 4u);
    EXPECT_EQ(mesh.source, path);
    // STL has no materials: assimp's default material is reported as none.
    EXPECT_TRUE(m.materials.empty());
    EXPECT_EQ(m.mesh_material, (std::vector<int>{-1}));
    ASSERT_EQ(mesh.normals.size(), mesh.vertexCount());
    Bounds3 b = mesh.bounds();
    EXPECT_EQ(b.lo, vec3(0.0f));
    EXPECT_EQ(b.hi, vec3(1.0f));
    // Faces point outwards: every normal points away from the centroid.
    vec3 c(0.25f);
    for (const uvec3& t : mesh.triangles) {
      vec3 a = mesh.positions[t.x], b2 = mesh.positions[t.y], d = mesh.positions[t.z];
      EXPECT_GT(glm::dot(glm::cross(b2 - a, d - a), (a + b2 + d) / 3.0f - c), 0.0f);
    }
  }
}

TEST(AssimpReader, ReadsBinaryStlAndOff) {
  TempDir dir;
  test::Bytes b(false);
  std::string header(80, ' ');
  b.put(uint32_t(1));
  for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 2.f, 0.f, 0.f, 0.f, 2.f, 0.f}) b.put(v);
  b.put(uint16_t(0));
  std::string stl = dir.write("tri.stl", header + b.str());
  LoadedModel m = loadModel(stl);
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_EQ(m.meshes[0].triangleCount(), 1u);
  EXPECT_EQ(m.meshes[0].bounds().hi, vec3(2, 2, 0));

  // OFF: a square of two triangles and a quad face.
  std::string off = dir.write("square.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  LoadedModel o = loadModel(off);
  ASSERT_EQ(o.meshes.size(), 1u);
  EXPECT_EQ(o.meshes[0].triangleCount(), 2u);
  for (const vec3& n : o.meshes[0].normals)
    EXPECT_NEAR(glm::distance(n, vec3(0, 0, 1)), 0.0f, 1e-5f);
}

TEST(AssimpErrors, MalformedFilesNameTheFile) {
  TempDir dir;
  std::string empty = dir.write("empty.stl", "");
  expectInputError([&] { loadWithAssimp(empty); }, {empty});
  std::string garbage = dir.write("garbage.3ds", std::string(300, '\x7f'));
  expectInputError([&] { loadWithAssimp(garbage); }, {garbage});
  // A binary STL claiming 1000 triangles with data for one. (Not a cut ASCII STL: assimp 5.2
  // leaks two allocations on those, which fails the asan preset's leak check.)
  test::Bytes b(false);
  b.put(uint32_t(1000));
  std::string cut = dir.write("cut.stl", std::string(80, ' ') + b.str() + std::string(50, '\0'));
  expectInputError([&] { loadModel(cut); }, {cut});
  std::string off = dir.write("cut.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n");
  expectInputError([&] { loadModel(off); }, {off});
  std::string missing = dir.file("missing.fbx");
  expectInputError([&] { loadModel(missing); }, {missing, "no such file"});
}

TEST(AssimpErrors, LimitsApply) {
  TempDir dir;
  std::string path = dir.write("tetra.stl", tetraStl());
  LoadLimits limits;
  limits.max_triangles = 3;
  expectInputError([&] { loadWithAssimp(path, limits); }, {path, "4 triangles", "max_triangles"});
}

}  // namespace
}  // namespace mirage
