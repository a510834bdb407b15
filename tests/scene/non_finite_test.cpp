// NaN and infinities in input: positions and texture coordinates are refused with the vertex's
// number, broken normals recomputed, float image pixels replaced (docs/reliability.md).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/image.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"
#include "support/test_files.h"

namespace mirage {
namespace {

using test::expectInputError;

std::string plyTriangle(const std::string& second_vertex, const std::string& extra_header = "",
                        const std::string& extra = "") {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\n" +
         extra_header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
         "0 0 0" + extra + "\n" + second_vertex + "\n0 1 0" + extra + "\n3 0 1 2\n";
}

// Every model file a scene names is read through loadMesh/loadModel, where the policy holds.
std::string fileWith(const std::string& name, const std::string& text) {
  const auto path = test::testTempDir("nonfinite") / name;
  test::writeText(path, text);
  return path.string();
}

TEST(NonFinite, PositionsAreRefusedNamingTheVertex) {
  for (const char* v : {"nan 0 0", "1 inf 0", "1 0 -inf"}) {
    const std::string ply = fileWith("bad.ply", plyTriangle(v));
    expectInputError([&] { loadMesh(ply); }, {ply, "vertex 1", "non-finite position"});
  }
  // OBJ counts its vertices from 1; tinyobjloader would read "nan" and "inf" as 0.
  for (const char* v : {"nan 0 0", "1 -inf 0", "1e39 0 0", "0 0 NaN"}) {
    const std::string obj =
        fileWith("bad.obj", std::string("v 0 0 0\nv ") + v + "\nv 0 1 0\nf 1 2 3\n");
    expectInputError([&] { loadMesh(obj); }, {obj, "vertex 2", "non-finite position"});
  }
}

TEST(NonFinite, TextureCoordinatesAreRefusedNormalsRecomputed) {
  const std::string uv_header = "property float u\nproperty float v\n";
  const std::string uv = fileWith("uv.ply", plyTriangle("1 0 0 nan 0", uv_header, " 0 0"));
  expectInputError([&] { loadMesh(uv); }, {uv, "vertex 1", "non-finite texture coordinates"});
  const std::string n_header = "property float nx\nproperty float ny\nproperty float nz\n";
  const Mesh m = loadMesh(fileWith("n.ply", plyTriangle("1 0 0 nan nan nan", n_header, " 0 0 1")));
  ASSERT_EQ(m.normals.size(), 3u);
  for (const vec3& n : m.normals) {
    EXPECT_TRUE(isFinite(n));
    EXPECT_NEAR(std::abs(n.z), 1.0f, 1e-6f);  // the triangle's own normal
  }
}

TEST(NonFinite, FloatPixelsAreReplaced) {
  const auto dir = test::testTempDir("nonfinite-exr");
  const float inf = std::numeric_limits<float>::infinity();
  Image image(2, 1, vec4(0.5f));
  image(0, 0) = vec4(std::nanf(""), inf, -inf, 1.0f);
  const std::string path = (dir / "bad.exr").string();
  writeExr(path, image);
  const Image read = readImage(path);
  EXPECT_EQ(read(0, 0), vec4(0.0f, 65504.0f, 0.0f, 1.0f));
  EXPECT_EQ(read(1, 0), vec4(0.5f));
}

}  // namespace
}  // namespace mirage
