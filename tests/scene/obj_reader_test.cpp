// The OBJ reader with .mtl materials: grouping per (shape, material), vertex de-duplication,
// textures relative to the .mtl, the reflector rule, and malformed files.
#include <gtest/gtest.h>

#include "core/image.h"
#include "scene/model_loader.h"
#include "scene/log_capture.h"
#include "scene/model_loader_files.h"

namespace mirage {
namespace {

using test::expectInputError;
using test::TempDir;

// A mirror quad (its own shape), then a box side and top in two materials of one shape.
const char* kObj = R"(# test scene
mtllib looks.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
vn 0 1 0
o mirror
usemtl chrome
f 1/1/1 2/2/1 3/3/1 4/4/1
o box
usemtl textured
f 1/1/1 2/2/1 3/3/1
f 1/1/1 3/3/1 4/4/1
usemtl plain
f 1//2 5//2 6//2 2//2
)";

const char* kMtl = R"(newmtl chrome
Kd 0.1 0.1 0.1
Ks 0.9 0.8 0.7
illum 3

newmtl textured
Kd 0.5 0.5 0.5
map_Kd -s 1 1 1 maps\albedo.png
norm maps/normal.png

newmtl plain
Kd 0.2 0.4 0.6
illum 2
)";

struct ObjFiles {
  TempDir dir;
  std::string obj;
  ObjFiles(const std::string& obj_text = kObj, const std::string& mtl_text = kMtl) {
    std::filesystem::create_directories(dir.file("models/maps"));
    writePng(dir.file("models/maps/albedo.png"), Image(2, 2, vec4(0.5f, 0.5f, 0.5f, 1.0f)));
    writePng(dir.file("models/maps/normal.png"), Image(2, 2, vec4(0.5f, 0.5f, 1.0f, 1.0f)));
    dir.write("models/looks.mtl", mtl_text);
    obj = dir.write("models/scene.obj", obj_text);
  }
};

TEST(ObjReader, GroupsByShapeAndMaterial) {
  ObjFiles f;
  LoadedModel m = loadObj(f.obj);
  ASSERT_EQ(m.meshes.size(), 3u);
  EXPECT_EQ(m.meshes[0].name, "mirror");
  EXPECT_EQ(m.meshes[1].name, "box/textured");
  EXPECT_EQ(m.meshes[2].name, "box/plain");
  ASSERT_EQ(m.materials.size(), 3u);
  EXPECT_EQ(m.mesh_material, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(m.materials[0].name, "chrome");
  for (const mat4& t : m.mesh_transform) EXPECT_EQ(t, mat4(1.0f));
  for (const Mesh& mesh : m.meshes) {
    EXPECT_EQ(mesh.source, f.obj);
    mesh.validate();
  }
}

TEST(ObjReader, DeduplicatesCornersByIndexTriple) {
  ObjFiles f;
  LoadedModel m = loadObj(f.obj);
  // The quad's 4 corners make 4 vertices and 2 fan triangles.
  const Mesh& quad = m.meshes[0];
  ASSERT_EQ(quad.vertexCount(), 4u);
  EXPECT_EQ(quad.triangles, (std::vector<uvec3>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(quad.positions[2], vec3(1, 1, 0));
  EXPECT_EQ(quad.normals[2], vec3(0, 0, 1));
  // OBJ and mirage share the bottom-left texture origin: uvs are kept as written.
  EXPECT_EQ(quad.uvs[3], vec2(0, 1));
  // Two triangles sharing two corners: 4 vertices, not 6.
  EXPECT_EQ(m.meshes[1].vertexCount(), 4u);
  // No texture coordinates in the last group.
  EXPECT_TRUE(m.meshes[2].uvs.empty());
  EXPECT_EQ(m.meshes[2].normals[0], vec3(0, 1, 0));

  // The same position with two normals gives two vertices.
  std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 1 0 0\n"
      "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n";
  TempDir dir;
  LoadedModel split = loadObj(dir.write("split.obj", obj));
  ASSERT_EQ(split.meshes.size(), 1u);
  EXPECT_EQ(split.meshes[0].vertexCount(), 6u);
  EXPECT_EQ(split.mesh_material, (std::vector<int>{-1}));
}

TEST(ObjReader, MaterialsTexturesAndReflectors) {
  ObjFiles f;
  LoadedModel m = loadObj(f.obj);
  const Material& chrome = m.materials[0];
  EXPECT_TRUE(chrome.isReflector());
  EXPECT_EQ(chrome.albedo, vec3(0.1f));            // base = Kd
  EXPECT_EQ(chrome.tint, vec3(0.9f, 0.8f, 0.7f));  // tint = Ks
  EXPECT_EQ(chrome.fresnel_f0, 1.0f);

  const Material& textured = m.materials[1];
  EXPECT_FALSE(textured.isReflector());
  EXPECT_EQ(textured.albedo, vec3(0.5f));
  ASSERT_EQ(m.textures.size(), 2u);
  ASSERT_EQ(textured.albedo_texture, 0);
  EXPECT_TRUE(m.textures[0].srgb);
  // A Windows path separator in the .mtl is read as '/'.
  EXPECT_NE(m.textures[0].name.find("maps/albedo.png"), std::string::npos);
  EXPECT_NEAR(m.textures[0].image(0, 0).x, srgbToLinear(128.0f / 255.0f), 1e-5f);
  ASSERT_EQ(textured.normal_map, 1);
  EXPECT_FALSE(m.textures[1].srgb);
  EXPECT_NEAR(m.textures[1].image(0, 0).x, 128.0f / 255.0f, 1e-5f);
  // Its mesh has uvs and a normal map: tangents along +u = +X.
  ASSERT_EQ(m.meshes[1].tangents.size(), 4u);
  EXPECT_NEAR(glm::distance(vec3(m.meshes[1].tangents[0]), vec3(1, 0, 0)), 0.0f, 1e-5f);

  EXPECT_FALSE(m.materials[2].isReflector());
  EXPECT_EQ(m.materials[2].albedo, vec3(0.2f, 0.4f, 0.6f));
}

TEST(ObjReader, OtherReflectorRules) {
  std::string mtl = R"(newmtl fresnel
Kd 0 0 0
Ks 0.5 0.5 0.25
illum 5
newmtl exported
Kd 0 0 0
Ks 1 1 1
Ns 1000
newmtl pbr
Kd 0.9 0.6 0.3
Pm 1
Pr 0
newmtl bare
illum 3
newmtl glossy
Kd 0.5 0.5 0.5
Ks 1 1 1
Ns 900
)";
  std::string obj = "mtllib looks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (const char* name : {"fresnel", "exported", "pbr", "bare", "glossy"})
    obj += fmt::format("o {0}\nusemtl {0}\nf 1 2 3\n", name);
  ObjFiles f(obj, mtl);
  LoadedModel m = loadObj(f.obj);
  ASSERT_EQ(m.materials.size(), 5u);
  const Material& fresnel = m.materials[0];
  EXPECT_TRUE(fresnel.isReflector());
  EXPECT_EQ(fresnel.fresnel_f0, 0.5f);
  EXPECT_EQ(fresnel.tint, vec3(1.0f, 1.0f, 0.5f));
  EXPECT_TRUE(m.materials[1].isReflector());
  EXPECT_EQ(m.materials[1].tint, vec3(1.0f));
  const Material& pbr = m.materials[2];
  EXPECT_TRUE(pbr.isReflector());
  EXPECT_EQ(pbr.tint, vec3(0.9f, 0.6f, 0.3f));
  EXPECT_EQ(pbr.albedo, vec3(0.05f));
  EXPECT_TRUE(m.materials[3].isReflector());
  EXPECT_EQ(m.materials[3].tint, vec3(1.0f));  // black Ks: a plain mirror
  EXPECT_FALSE(m.materials[4].isReflector());  // Ns 900: glossy, not a mirror
}

TEST(ObjReader, ComputesMissingNormalsAndTriangulatesPolygons) {
  TempDir dir;
  std::string obj = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n";
  LoadedModel m = loadObj(dir.write("pentagon.obj", obj));
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_EQ(m.meshes[0].triangleCount(), 3u);
  for (const vec3& n : m.meshes[0].normals)
    EXPECT_NEAR(glm::distance(n, vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(ObjReader, MissingMtlFileLeavesDefaultMaterials) {
  TempDir dir;
  std::string obj = "mtllib nowhere.mtl\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  LoadedModel m = loadObj(dir.write("lonely.obj", obj));
  EXPECT_TRUE(m.materials.empty());
  EXPECT_EQ(m.mesh_material, (std::vector<int>{-1}));
}

// A texture whose file does not exist is left out with one warning per file, as Blender, assimp's
// viewer and three.js do (assimp's FBX/spider.fbx names D:/projects/...): the material stays,
// without it. A file named by a path of another machine is looked for by its name alone in the
// material file's folder. Both readers alike: tinyobjloader's and assimp's.
TEST(ObjReader, AMissingTextureIsLeftOutWithAWarningAndAForeignPathFoundByName) {
  const std::string mtl =
      "newmtl wood\nKd 1 1 1\nmap_Kd wood.jpg\nnewmtl oak\nKd 1 1 1\nmap_Kd wood.jpg\n"
      "newmtl moved\nKd 1 1 1\nmap_Kd D:\\projects\\spider\\maps\\albedo.png\n";
  const std::string obj =
      "mtllib looks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl wood\nf 1 2 3\nusemtl oak\n"
      "f 1 2 3\nusemtl moved\nf 1 2 3\n";
  ObjFiles f(obj, mtl);
  writePng(f.dir.file("models/albedo.png"), Image(2, 2, vec4(0.5f, 0.5f, 0.5f, 1.0f)));
  for (const bool assimp : {false, true}) {
    SCOPED_TRACE(assimp ? "assimp" : "tinyobjloader");
    test::LogCapture log;
    const LoadedModel m = assimp ? loadWithAssimp(f.obj) : loadObj(f.obj);
    ASSERT_EQ(m.materials.size(), 3u);
    for (const Material& material : m.materials) {
      if (material.name == "moved")
        EXPECT_GE(material.albedo_texture, 0) << "found by its name beside the materials";
      else
        EXPECT_EQ(material.albedo_texture, -1) << material.name;
    }
    EXPECT_EQ(log.count({"warning", "wood.jpg", "does not exist"}), 1u) << "once per file";
  }
}

TEST(ObjErrors, UnreadableTextureNamesBothFiles) {
  std::string mtl = "newmtl wood\nKd 1 1 1\nmap_Kd maps/looks.png\n";
  std::string obj = "mtllib looks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl wood\nf 1 2 3\n";
  ObjFiles f(obj, mtl);
  f.dir.write("models/maps/looks.png", "not a png");
  expectInputError([&] { loadObj(f.obj); }, {f.dir.file("models/looks.mtl"), "looks.png"});
}

TEST(ObjErrors, IndicesOutOfRange) {
  TempDir dir;
  std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  std::string path = dir.write("bad.obj", v + "f 1 2 9\n");
  expectInputError([&] { loadObj(path); }, {path, "v/vt/vn 9/0/0", "3 v"});
  path = dir.write("badvt.obj", v + "f 1/1 2/1 3/4\n");
  expectInputError([&] { loadObj(path); }, {path, "3/4/0", "1 vt"});
  path = dir.write("badvn.obj", v + "f 1//1 2//1 3//2\n");
  expectInputError([&] { loadObj(path); }, {path, "3/0/2", "1 vn"});
  path = dir.write("zero.obj", v + "f 0 1 2\n");
  expectInputError([&] { loadObj(path); }, {path});
}

TEST(ObjErrors, EmptyFilesAndLimits) {
  TempDir dir;
  std::string empty = dir.write("empty.obj", "");
  expectInputError([&] { loadObj(empty); }, {empty, "no faces"});
  std::string points = dir.write("points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n");
  expectInputError([&] { loadObj(points); }, {points, "no faces"});
  std::string tri = dir.write("tri.obj", "v 0 0 0\nv 1 0 0\n  v 0 1 0\nf 1 2 3\n");
  LoadLimits limits;
  limits.max_vertices = 2;
  expectInputError([&] { loadObj(tri, limits); }, {tri, "3 vertices", "max_vertices"});
  limits = LoadLimits{};
  limits.max_triangles = 1;
  std::string quad = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  expectInputError([&] { loadObj(quad, limits); }, {quad, "2 triangles", "max_triangles"});
}

}  // namespace
}  // namespace mirage
