// The PLY reader on files written by the tests: every encoding, type, property layout and gzip.
#include <gtest/gtest.h>

#include "scene/model_loader.h"
#include "scene/model_loader_files.h"
#include "scene/ply_header.h"
#include "scene/ply_test_writer.h"

namespace mirage {
namespace {

using test::PlyElem;
using test::TempDir;

const char* const kFormats[] = {"ascii", "binary_little_endian", "binary_big_endian"};

// The cube as the reader must return it: 8 vertices, 12 triangles, outward smooth normals.
void expectCube(const Mesh& m) {
  ASSERT_EQ(m.vertexCount(), 8u);
  ASSERT_EQ(m.triangleCount(), 12u);
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(m.positions[size_t(i)], vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)));
  ASSERT_EQ(m.normals.size(), 8u);
  // Every corner touches three faces with two triangles each: the normal is the diagonal.
  vec3 n7 = glm::normalize(vec3(1.0f));
  EXPECT_NEAR(glm::distance(m.normals[7], n7), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(m.normals[0], -n7), 0.0f, 1e-5f);
  // Fan triangulation of quad {0, 2, 3, 1}.
  EXPECT_EQ(m.triangles[0], uvec3(0, 2, 3));
  EXPECT_EQ(m.triangles[1], uvec3(0, 3, 1));
  m.validate();
}

TEST(PlyReader, ReadsTheCubeInEveryEncoding) {
  TempDir dir;
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    std::string path =
        dir.write(std::string(format) + ".ply", test::writePly(test::cubeElements(), format));
    Mesh m = loadPly(path);
    expectCube(m);
    EXPECT_EQ(m.source, path);
    EXPECT_EQ(m.name, format);
    EXPECT_TRUE(m.uvs.empty());
  }
}

TEST(PlyReader, ReadsEveryScalarTypeForCoordinatesAndIndices) {
  // Coordinates of each type (sized and classic names), indices of each integer type.
  const std::pair<const char*, const char*> kTypes[] = {
      {"char", "uchar"},   {"int8", "uint8"},    {"short", "ushort"}, {"int16", "uint16"},
      {"int", "uint"},     {"int32", "uint32"},  {"float", "int"},    {"float32", "int32"},
      {"double", "short"}, {"float64", "uint16"}};
  for (const char* format : kFormats)
    for (auto [coord, index] : kTypes) {
      SCOPED_TRACE(fmt::format("{} {} {}", format, coord, index));
      for (const char* count : {"uchar", "int", "uint16"})
        expectCube(
            readPly("cube.ply", test::writePly(test::cubeElements(coord, count, index), format)));
    }
}

TEST(PlyReader, KeepsFloat64Precision) {
  std::vector<PlyElem> e = test::cubeElements("float64");
  e[0].rows[1][0][0] = 1.0 + 1e-7;  // survives double -> float only if parsed as double first
  e[0].rows[2][1][0] = -123456.75;
  for (const char* format : kFormats) {
    Mesh m = readPly("cube.ply", test::writePly(e, format));
    EXPECT_EQ(m.positions[1].x, float(1.0 + 1e-7)) << format;
    EXPECT_EQ(m.positions[2].y, -123456.75f) << format;
  }
}

TEST(PlyReader, SkipsUnknownPropertiesAndElementsInEveryEncoding) {
  PlyElem v{"vertex",
            {{"uchar", "red", ""},
             {"float", "x", ""},
             {"int", "adjacent", "uchar"},  // a list inside the vertex element
             {"float", "y", ""},
             {"double", "confidence", ""},
             {"float", "z", ""},
             {"float", "nx", ""},
             {"float", "ny", ""},
             {"float", "nz", ""},
             {"short", "s", ""},
             {"short", "t", ""}},
            {}};
  std::vector<std::vector<double>> p = test::cubeVertices();
  for (size_t i = 0; i < 8; ++i)
    v.rows.push_back({{200},
                      {p[i][0]},
                      {1, 2, double(i)},
                      {p[i][1]},
                      {0.25},
                      {p[i][2]},
                      {0},
                      {0},
                      {2},  // unnormalised on purpose
                      {double(i)},
                      {double(10 + i)}});
  PlyElem edges{"edge",
                {{"int", "vertex1", ""}, {"int", "vertex2", ""}, {"float", "w", "int"}},
                {{{0}, {1}, {}}, {{1}, {2}, {0.5, 0.5}}}};
  PlyElem faces{
      "face",
      {{"int", "flags", ""}, {"uint", "vertex_index", "uint8"}, {"float", "texcoord", "uchar"}},
      {}};
  for (const auto& q : test::cubeQuads()) faces.rows.push_back({{7}, q, {0, 1, 0, 1, 1, 1, 0, 0}});
  PlyElem material{"material", {{"float", "ambient", ""}}, {{{0.5}}}};
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    Mesh m = readPly("extra.ply", test::writePly({edges, v, material, faces}, format,
                                                 "obj_info scanned by nobody\n"));
    ASSERT_EQ(m.vertexCount(), 8u);
    ASSERT_EQ(m.triangleCount(), 12u);
    EXPECT_EQ(m.positions[7], vec3(1.0f));
    // Normals come from the file, normalised.
    for (const vec3& n : m.normals) EXPECT_EQ(n, vec3(0, 0, 1));
    ASSERT_EQ(m.uvs.size(), 8u);
    EXPECT_EQ(m.uvs[3], vec2(3, 13));
  }
}

TEST(PlyReader, ReadsEveryTextureCoordinateNaming) {
  for (auto [u, v] : {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}}) {
    std::vector<PlyElem> e = test::cubeElements();
    e[0].props.push_back({"float", u, ""});
    e[0].props.push_back({"float", v, ""});
    for (size_t i = 0; i < 8; ++i) {
      e[0].rows[i].push_back({0.5 * double(i)});
      e[0].rows[i].push_back({0.25});
    }
    Mesh m = readPly("uv.ply", test::writePly(e, "ascii"));
    ASSERT_EQ(m.uvs.size(), 8u) << u;
    EXPECT_EQ(m.uvs[4], vec2(2.0f, 0.25f)) << u;
  }
}

TEST(PlyReader, ReadsTriangleStrips) {
  std::vector<PlyElem> e = test::cubeElements();
  // The -Z quad as a strip 2 0 3 1, then a restart and the +Z quad as 4 5 6 7.
  e[1] =
      PlyElem{"tristrips", {{"int", "vertex_indices", "uint"}}, {{{2, 0, 3, 1, -1, 4, 5, 6, 7}}}};
  Mesh m = readPly("strips.ply", test::writePly(e, "binary_little_endian"));
  ASSERT_EQ(m.triangleCount(), 4u);
  EXPECT_EQ(m.triangles[0], uvec3(2, 0, 3));
  EXPECT_EQ(m.triangles[1], uvec3(3, 0, 1));  // odd triangles swap to keep the winding
  EXPECT_EQ(m.triangles[2], uvec3(4, 5, 6));
  EXPECT_EQ(m.triangles[3], uvec3(6, 5, 7));
}

TEST(PlyReader, ToleratesCrLfAndBlankLinesAndPlusSigns) {
  std::string text =
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n"
      "end_header\r\n0 0 0\r\n\r\n+1 0 0\r\n0 1e0 0\r\n3 0 1 2";  // no final newline
  Mesh m = readPly("crlf.ply", text);
  EXPECT_EQ(m.triangleCount(), 1u);
  EXPECT_EQ(m.positions[1], vec3(1, 0, 0));
  EXPECT_EQ(m.normals[0], vec3(0, 0, 1));
}

// Exporters write free-text header lines that are not `comment` lines; common readers accept
// them. Each becomes a comment with a warning naming its line, in every encoding.
TEST(PlyReader, ReadsFreeTextHeaderLinesAsCommentsWithAWarning) {
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    std::string text = test::writePly(test::cubeElements(), format);
    const std::string format_line = std::string("format ") + format + " 1.0\n";
    const size_t at = text.find(format_line) + format_line.size();
    text.insert(at, "Exported by ScanStudio 4.2 (units: mm)\n\tTextureFile none\n");
    const ply::Header h = ply::parseHeader("free.ply", text);
    ASSERT_EQ(h.warnings.size(), 2u);
    EXPECT_NE(h.warnings[0].find("free.ply: line 3: 'Exported by ScanStudio"), std::string::npos)
        << h.warnings[0];
    EXPECT_NE(h.warnings[1].find("line 4"), std::string::npos) << h.warnings[1];
    expectCube(readPly("free.ply", text));
  }
}

TEST(PlyReader, ReadsGzipFilesAndBytes) {
  TempDir dir;
  for (const char* format : kFormats) {
    std::string gz = test::gzip(test::writePly(test::cubeElements(), format));
    std::string path = dir.write(std::string(format) + ".ply.gz", gz);
    Mesh m = loadPly(path);
    expectCube(m);
    EXPECT_EQ(m.name, format);  // both extensions dropped
    expectCube(readPly("memory.ply.gz", gz));
  }
  // Two concatenated members, as `cat a.gz b.gz` makes them.
  std::string text = test::writePly(test::cubeElements(), "ascii");
  expectCube(readPly("two.ply.gz", test::gzip(text.substr(0, 100)) + test::gzip(text.substr(100))));
}

}  // namespace
}  // namespace mirage
