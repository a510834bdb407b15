// Midpoint subdivision (subdivideMidpoint): V + E vertices and 4T triangles, the same surface
// (bounds, area, every new vertex on its original triangle, orientation), closed meshes stay
// closed; and the scene files' "subdivide" field on a mesh file, with its range check.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "scene/ply_test_writer.h"
#include "scene/procedural.h"
#include "scene/scene_json.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

using Edge = std::pair<uint32_t, uint32_t>;

// How many triangles use each undirected edge.
std::map<Edge, int> edgeUses(const Mesh& m) {
  std::map<Edge, int> uses;
  for (const uvec3& t : m.triangles)
    for (auto [a, b] : {Edge{t.x, t.y}, Edge{t.y, t.z}, Edge{t.z, t.x}})
      ++uses[{std::min(a, b), std::max(a, b)}];
  return uses;
}

bool isClosed(const Mesh& m) {
  for (const auto& [edge, count] : edgeUses(m))
    if (count != 2) return false;
  return true;
}

double area(const Mesh& m) {
  double sum = 0.0;
  for (const uvec3& t : m.triangles) {
    glm::dvec3 a(m.positions[t.x]), b(m.positions[t.y]), c(m.positions[t.z]);
    sum += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return sum;
}

vec3 faceNormal(const Mesh& m, const uvec3& t) {
  return glm::normalize(
      glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]));
}

// The mesh with vertices at equal positions merged (the procedural box has four per face).
Mesh welded(const Mesh& m) {
  auto less = [](const vec3& a, const vec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  };
  std::map<vec3, uint32_t, decltype(less)> index(less);
  std::vector<uint32_t> remap;
  Mesh out;
  out.name = m.name;
  for (const vec3& p : m.positions) {
    auto [it, inserted] = index.try_emplace(p, uint32_t(out.positions.size()));
    if (inserted) out.positions.push_back(p);
    remap.push_back(it->second);
  }
  for (const uvec3& t : m.triangles) out.triangles.push_back({remap[t.x], remap[t.y], remap[t.z]});
  out.computeNormals();
  return out;
}

// Everything subdivideMidpoint promises about `m`, subdivided once.
void expectSubdivisionOf(const Mesh& m) {
  SCOPED_TRACE(m.name);
  const size_t edges = edgeUses(m).size();
  Mesh s = subdivideMidpoint(m);
  EXPECT_NO_THROW(s.validate());
  EXPECT_EQ(s.vertexCount(), m.vertexCount() + edges);
  EXPECT_EQ(s.triangleCount(), 4 * m.triangleCount());
  EXPECT_EQ(s.normals.size(), s.positions.size());
  EXPECT_EQ(s.uvs.size(), m.uvs.empty() ? 0u : s.positions.size());
  EXPECT_EQ(s.tangents.size(), m.tangents.empty() ? 0u : s.positions.size());
  EXPECT_EQ(s.name, m.name);
  EXPECT_EQ(s.source, m.source);

  // The original vertices come first, unchanged.
  for (size_t i = 0; i < m.vertexCount(); ++i) ASSERT_EQ(s.positions[i], m.positions[i]) << i;
  Bounds3 a = m.bounds(), b = s.bounds();
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  EXPECT_NEAR(area(s), area(m), 1e-5 * area(m));

  for (const vec3& n : s.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  for (const vec4& t : s.tangents) EXPECT_NEAR(glm::length(vec3(t)), 1.0f, 1e-5f);

  // Triangle i becomes triangles 4i..4i+3: each child's corners lie on triangle i (its plane,
  // barycentric coordinates in [0, 1]), the children face the same way and cover its area.
  const float scale = glm::length(a.extent());
  for (size_t i = 0; i < m.triangleCount(); ++i) {
    const uvec3& t = m.triangles[i];
    vec3 p0 = m.positions[t.x], p1 = m.positions[t.y], p2 = m.positions[t.z];
    vec3 n = faceNormal(m, t);
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    float det = d11 * d22 - d12 * d12;
    double child_area = 0.0;
    for (size_t c = 4 * i; c < 4 * i + 4; ++c) {
      const uvec3& ct = s.triangles[c];
      EXPECT_GT(glm::dot(faceNormal(s, ct), n), 0.999f) << "triangle " << i << " child " << c;
      for (uint32_t v : {ct.x, ct.y, ct.z}) {
        vec3 q = s.positions[v] - p0;
        EXPECT_NEAR(glm::dot(q, n), 0.0f, 1e-6f * scale) << "vertex " << v << " off triangle " << i;
        float u = (d22 * glm::dot(q, e1) - d12 * glm::dot(q, e2)) / det;
        float w = (d11 * glm::dot(q, e2) - d12 * glm::dot(q, e1)) / det;
        EXPECT_GE(u, -1e-5f);
        EXPECT_GE(w, -1e-5f);
        EXPECT_LE(u + w, 1.0f + 1e-5f);
      }
      glm::dvec3 a0(s.positions[ct.x]), a1(s.positions[ct.y]), a2(s.positions[ct.z]);
      child_area += 0.5 * glm::length(glm::cross(a1 - a0, a2 - a0));
    }
    EXPECT_NEAR(child_area, 0.5 * glm::length(glm::cross(glm::dvec3(e1), glm::dvec3(e2))),
                1e-5 * child_area + 1e-12);
  }

  // Every new vertex is the midpoint of one original edge, with the edge's interpolated uv.
  std::map<uint32_t, Edge> midpoint_of;
  for (size_t i = 0; i < m.triangleCount(); ++i) {
    const uvec3& t = m.triangles[i];
    const uvec3& centre = s.triangles[4 * i + 3];
    for (auto [mid, edge] :
         {std::pair{centre.x, Edge{t.x, t.y}}, std::pair{centre.y, Edge{t.y, t.z}},
          std::pair{centre.z, Edge{t.z, t.x}}}) {
      ASSERT_GE(mid, m.vertexCount());
      Edge sorted{std::min(edge.first, edge.second), std::max(edge.first, edge.second)};
      auto [it, inserted] = midpoint_of.try_emplace(mid, sorted);
      EXPECT_EQ(it->second, sorted) << "vertex " << mid << " is the midpoint of two edges";
      EXPECT_EQ(s.positions[mid], 0.5f * (m.positions[edge.first] + m.positions[edge.second]));
      if (!m.uvs.empty()) {
        EXPECT_EQ(s.uvs[mid], 0.5f * (m.uvs[edge.first] + m.uvs[edge.second]));
      }
    }
  }
  EXPECT_EQ(midpoint_of.size(), edges);
}

TEST(MeshSubdivide, ProceduralBoxAndSphereKeepTheirSurface) {
  expectSubdivisionOf(procedural::box({0.5f, 1.0f, 1.5f}));
  expectSubdivisionOf(procedural::sphere(2.0f, 24, 12));
  expectSubdivisionOf(procedural::torus(1.0f, 0.3f, 16, 8));
  Mesh twice = subdivideMidpoint(subdivideMidpoint(procedural::sphere(1.0f, 12, 6)));
  twice.name = "sphere subdivided twice";
  expectSubdivisionOf(twice);
}

TEST(MeshSubdivide, ClosedMeshesStayClosed) {
  Mesh cube = welded(procedural::box(vec3(1.0f)));
  ASSERT_EQ(cube.vertexCount(), 8u);
  ASSERT_TRUE(isClosed(cube));
  expectSubdivisionOf(cube);
  Mesh once = subdivideMidpoint(cube);
  EXPECT_EQ(once.vertexCount(), 8u + 18u);  // V + E
  EXPECT_EQ(once.triangleCount(), 48u);
  EXPECT_TRUE(isClosed(once));
  Mesh twice = subdivideMidpoint(once);
  EXPECT_EQ(twice.vertexCount(), 26u + 72u);
  EXPECT_EQ(twice.triangleCount(), 192u);
  EXPECT_TRUE(isClosed(twice));
  // Euler characteristic of a sphere: V - E + F = 2 after every round.
  for (const Mesh* m : {&cube, &once, &twice})
    EXPECT_EQ(int(m->vertexCount()) - int(edgeUses(*m).size()) + int(m->triangleCount()), 2);
}

TEST(MeshSubdivide, NormalsTangentsAndDegenerateEdges) {
  // Two triangles sharing edge 1-2, whose end normals cancel: the midpoint takes the face normal.
  Mesh m;
  m.name = "pair";
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.normals = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}};
  m.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  m.tangents = {{1, 0, 0, 1}, {0, 1, 0, -1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  Mesh s = subdivideMidpoint(m);
  ASSERT_EQ(s.vertexCount(), 4u + 5u);
  ASSERT_EQ(s.triangleCount(), 8u);
  // The shared edge 1-2 has one midpoint, used by both triangles' centre children.
  uint32_t shared = s.triangles[3].y;
  EXPECT_EQ(s.triangles[7].z, shared);
  EXPECT_EQ(s.positions[shared], vec3(0.5f, 0.5f, 0.0f));
  EXPECT_EQ(s.normals[shared], vec3(0, 0, 1));
  // Edge 0-1: normalize((0,0,1) + (1,0,0)); its tangent normalised, w from the first end.
  uint32_t m01 = s.triangles[0].y;
  EXPECT_NEAR(glm::distance(s.normals[m01], glm::normalize(vec3(1, 0, 1))), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(vec3(s.tangents[m01]), glm::normalize(vec3(1, 1, 0))), 0.0f, 1e-6f);
  EXPECT_EQ(s.tangents[m01].w, 1.0f);
  uint32_t m13 = s.triangles[4].y;  // edge 1-3 starts at vertex 1 (w = -1)
  EXPECT_EQ(s.tangents[m13].w, -1.0f);
  EXPECT_EQ(s.uvs[m13], vec2(1.0f, 0.5f));

  // Without normals, uvs or tangents the result has none either.
  Mesh bare;
  bare.positions = m.positions;
  bare.triangles = m.triangles;
  Mesh b = subdivideMidpoint(bare);
  EXPECT_EQ(b.vertexCount(), 9u);
  EXPECT_TRUE(b.normals.empty() && b.uvs.empty() && b.tangents.empty());

  // A bad index is an InputError, not a crash.
  bare.triangles.push_back({0, 1, 7});
  EXPECT_THROW(subdivideMidpoint(bare), InputError);
}

// A scene with the PLY cube (8 vertices, 12 triangles) as a mesh with `extra` fields.
fs::path writeCubeScene(const fs::path& dir, const std::string& extra) {
  writeText(dir / "cube.ply", writePly(cubeElements(), "ascii"));
  std::string text = R"({"materials": [{"name": "m", "type": "reflector"}],
    "meshes": [{"name": "cube", "file": "cube.ply")" +
                     extra + R"(}],
    "instances": [{"mesh": "cube", "material": "m"}, {"name": "model", "model": "cube"}]})";
  writeText(dir / "scene.json", text);
  return dir / "scene.json";
}

TEST(MeshSubdivide, SceneFieldSubdividesMeshFiles) {
  fs::path dir = testTempDir("mesh-subdivide");
  Scene plain = loadSceneJson(writeCubeScene(dir, "").string());
  ASSERT_EQ(plain.instances.size(), 2u);
  const Mesh& cube = plain.meshes[size_t(plain.instances[0].mesh)];
  ASSERT_EQ(cube.triangleCount(), 12u);
  ASSERT_EQ(cube.vertexCount(), 8u);

  Scene once = loadSceneJson(
      writeCubeScene(dir, R"(, "subdivide": 1, "fit": {"size": 2, "ground": true})").string());
  for (const Instance& inst : once.instances) {  // the mesh and the model instance
    const Mesh& m = once.meshes[size_t(inst.mesh)];
    EXPECT_EQ(m.triangleCount(), 4u * 12u) << inst.name;
    EXPECT_EQ(m.vertexCount(), 8u + 18u) << inst.name;
    EXPECT_TRUE(isClosed(m)) << inst.name;
    // Subdivided after the fit: the fitted cube's bounds.
    EXPECT_NEAR(glm::distance(m.bounds().lo, vec3(-1, 0, -1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(m.bounds().hi, vec3(1, 2, 1)), 0.0f, 1e-6f);
  }

  Scene thrice = loadSceneJson(writeCubeScene(dir, R"(, "subdivide": 3)").string());
  EXPECT_EQ(thrice.meshes[size_t(thrice.instances[0].mesh)].triangleCount(), 12u * 64u);
  Scene none = loadSceneJson(writeCubeScene(dir, R"(, "subdivide": 0)").string());
  EXPECT_EQ(none.meshes[size_t(none.instances[0].mesh)].triangleCount(), 12u);
}

TEST(MeshSubdivide, SceneFieldOutsideZeroToFourIsAnInputError) {
  fs::path dir = testTempDir("mesh-subdivide");
  struct Bad {
    const char* value;
    const char* expected;
  };
  for (Bad bad : {Bad{"7", "meshes[0].subdivide = 7 is outside the allowed range 0..4"},
                  Bad{"-1", "meshes[0].subdivide = -1 is outside the allowed range 0..4"},
                  Bad{R"("x")", "meshes[0].subdivide = 'x': expected an integer in 0..4"},
                  Bad{"1.5", "meshes[0].subdivide = 1.5: expected an integer in 0..4"}}) {
    fs::path file = writeCubeScene(dir, std::string(R"(, "subdivide": )") + bad.value);
    try {
      loadSceneJson(file.string());
      ADD_FAILURE() << bad.value << ": no error";
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
      EXPECT_NE(msg.find(bad.expected), std::string::npos) << msg;
    }
  }
  // Only mesh files take it.
  writeText(dir / "proc.json", R"({"materials": [{"name": "m", "type": "diffuse"}],
    "meshes": [{"name": "b", "procedural": "box", "subdivide": 1}],
    "instances": [{"mesh": "b", "material": "m"}]})");
  try {
    loadSceneJson((dir / "proc.json").string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("meshes[0].subdivide: unknown field"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace mirage::test
