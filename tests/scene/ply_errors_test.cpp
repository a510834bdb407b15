// Malformed PLY files: each must fail with an InputError naming the file, and (ASCII) the line,
// and what was expected — and absurd header counts must fail at once, before any allocation.
#include <gtest/gtest.h>

#include "scene/model_loader.h"
#include "scene/model_loader_files.h"
#include "scene/ply_test_writer.h"

namespace mirage {
namespace {

using test::expectInputError;

std::string asciiCube() {
  return test::writePly(test::cubeElements(), "ascii");
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  size_t i = s.find(from);
  EXPECT_NE(i, std::string::npos) << from;
  return s.replace(i, from.size(), to);
}

TEST(PlyErrors, TruncatedBinaryData) {
  for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
    std::string full = test::writePly(test::cubeElements(), format);
    // Cut inside the last face: the header check passes (lists may be short), the read fails.
    expectInputError([&] { readPly("cut.ply", full.substr(0, full.size() - 3)); },
                     {"cut.ply", "face 5 of 6", "cut off"});
    // Cut inside the vertices: too few bytes for the declared counts at all.
    size_t header = full.find("end_header\n") + 11;
    expectInputError([&] { readPly("short.ply", full.substr(0, header + 20)); },
                     {"short.ply", "element vertex declares 8", "truncated file or wrong count"});
  }
}

TEST(PlyErrors, TruncatedGzip) {
  std::string gz = test::gzip(asciiCube());
  expectInputError([&] { readPly("cut.ply.gz", gz.substr(0, gz.size() / 2)); },
                   {"cut.ply.gz", "truncated"});
  std::string corrupt = gz;
  corrupt[12] = char(~corrupt[12]);
  corrupt[13] = char(~corrupt[13]);
  expectInputError([&] { readPly("bad.ply.gz", corrupt); }, {"bad.ply.gz"});
}

TEST(PlyErrors, DecompressedSizeIsCapped) {
  std::string gz = test::gzip(asciiCube() + std::string(100000, ' '));
  LoadLimits limits;
  limits.max_bytes = 10000;
  expectInputError([&] { readPly("bomb.ply.gz", gz, limits); },
                   {"bomb.ply.gz", "more than 9.8 KiB", "--max-memory"});
  limits.max_bytes = 1 << 20;
  EXPECT_EQ(readPly("fine.ply.gz", gz, limits).triangleCount(), 12u);
}

TEST(PlyErrors, WrongElementCounts) {
  std::string text = asciiCube();
  // One vertex more than present: the first face line is read as vertex 8 and has 5 values.
  // Header lines: ply, format, comment, element, 3 properties, element, property, end_header.
  expectInputError(
      [&] { readPly("more.ply", replace(text, "element vertex 8", "element vertex 9")); },
      {"more.ply", "line 19", "vertex 8 of 9", "more values than its 3 properties"});
  // One vertex fewer: vertex 7 is read as a face, then the data goes on past the last face.
  expectInputError(
      [&] { readPly("less.ply", replace(text, "element vertex 8", "element vertex 7")); },
      {"less.ply", "line 18", "face 0 of 6"});
  // A face too many: the file ends first.
  expectInputError([&] { readPly("faces.ply", replace(text, "element face 6", "element face 7")); },
                   {"faces.ply", "ends before face 6 of 7"});
  // A face too few: data left over.
  expectInputError([&] { readPly("extra.ply", replace(text, "element face 6", "element face 5")); },
                   {"extra.ply", "line 24", "unexpected data after the last element"});
  // A vertex line with a value missing.
  expectInputError([&] { readPly("short.ply", replace(text, "\n1 1 1\n", "\n1 1\n")); },
                   {"short.ply", "line 18", "vertex 7 of 8", "fewer values"});
}

TEST(PlyErrors, IndexOutOfRange) {
  std::vector<test::PlyElem> e = test::cubeElements();
  e[1].rows[3][0][2] = 8;
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    std::string msg = expectInputError([&] { readPly("index.ply", test::writePly(e, format)); },
                                       {"index.ply", "face 3 of 6", "refers to vertex 8", "0..7"});
    if (std::string(format) == "ascii") {
      EXPECT_NE(msg.find("line 22"), std::string::npos) << msg;
    }
  }
  e[1].rows[3][0][2] = -1;
  expectInputError([&] { readPly("negative.ply", test::writePly(e, "binary_little_endian")); },
                   {"negative.ply", "refers to vertex -1"});
}

TEST(PlyErrors, NonFiniteCoordinates) {
  expectInputError([&] { readPly("nan.ply", replace(asciiCube(), "\n1 1 1\n", "\n1 nan 1\n")); },
                   {"nan.ply", "line 18", "vertex 7 of 8", "non-finite"});
  expectInputError([&] { readPly("inf.ply", replace(asciiCube(), "\n1 1 1\n", "\n1 1 -inf\n")); },
                   {"inf.ply", "non-finite"});
  std::vector<test::PlyElem> e = test::cubeElements("double");
  e[0].rows[2][0][0] = std::numeric_limits<double>::quiet_NaN();
  expectInputError([&] { readPly("nan.ply", test::writePly(e, "binary_big_endian")); },
                   {"nan.ply", "vertex 2 of 8", "non-finite"});
  e[0].rows[2][0][0] = 1e300;  // finite as a double, infinite as a float
  expectInputError([&] { readPly("huge.ply", test::writePly(e, "binary_little_endian")); },
                   {"huge.ply", "non-finite"});
}

TEST(PlyErrors, AbsurdHeaderCountsFailFast) {
  std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1000000000000\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string file = header + std::string(200, '\0');
  // Caught by the limits...
  double s = test::secondsFor([&] {
    expectInputError([&] { readPly("absurd.ply", file); },
                     {"absurd.ply", "1000000000000 vertices", "max_vertices"});
  });
  EXPECT_LT(s, 0.1);
  // ... and, with limits lifted, by the bytes actually present, in every encoding.
  LoadLimits none{UINT64_MAX, UINT64_MAX, UINT64_MAX};
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    std::string f = replace(file, "binary_little_endian", format);
    s = test::secondsFor([&] {
      expectInputError([&] { readPly("absurd.ply", f, none); },
                       {"absurd.ply", "line 3", "declares 1000000000000", "200 bytes"});
    });
    EXPECT_LT(s, 0.1) << format;
  }
  // A count too large for 64 bits.
  expectInputError(
      [&] { readPly("big.ply", replace(file, "1000000000000", "99999999999999999999999")); },
      {"big.ply", "line 3", "is not a number"});
}

TEST(PlyErrors, LimitsOnTriangles) {
  LoadLimits limits;
  limits.max_triangles = 11;  // the cube's 6 faces pass the header check, its 12 triangles not
  expectInputError([&] { readPly("cube.ply", asciiCube(), limits); },
                   {"cube.ply", "more than 11 triangles", "max_triangles"});
  limits = LoadLimits{};
  limits.max_vertices = 7;
  expectInputError([&] { readPly("cube.ply", asciiCube(), limits); },
                   {"cube.ply", "8 vertices", "max_vertices"});
}

TEST(PlyErrors, EmptyAndForeignFiles) {
  expectInputError([&] { readPly("empty.ply", ""); }, {"empty.ply", "empty file"});
  expectInputError([&] { readPly("png.ply", "\x89PNG\r\n\x1a\n\0\0\0\rIHDR"); },
                   {"png.ply", "not a PLY file"});
  expectInputError([&] { readPly("obj.ply", "v 0 0 0\nv 1 0 0\nf 1 2 3\n"); },
                   {"obj.ply", "not a PLY file"});
  test::TempDir dir;
  std::string empty = dir.write("empty.ply", "");
  expectInputError([&] { loadPly(empty); }, {empty, "empty file"});
  expectInputError([&] { loadPly(dir.file("missing.ply")); }, {dir.file("missing.ply")});
}

TEST(PlyErrors, BadHeaderLines) {
  std::string text = asciiCube();
  expectInputError([&] { readPly("t.ply", replace(text, "property float y", "property flot y")); },
                   {"t.ply", "line 6", "unknown type 'flot'"});
  expectInputError([&] { readPly("t.ply", replace(text, "format ascii 1.0", "format utf8 1.0")); },
                   {"t.ply", "line 2", "unknown format 'utf8'"});
  expectInputError([&] { readPly("t.ply", replace(text, "format ascii 1.0", "format ascii 2.0")); },
                   {"t.ply", "line 2", "version"});
  expectInputError([&] { readPly("t.ply", replace(text, "element face 6", "element face six")); },
                   {"t.ply", "line 8", "count 'six'"});
  expectInputError([&] { readPly("t.ply", replace(text, "end_header", "end_headr")); },
                   {"t.ply", "line 10", "unknown header keyword 'end_headr'"});
  expectInputError([&] { readPly("t.ply", replace(text, "end_header\n", "")); },
                   {"t.ply", "line 10", "data before end_header"});
  // Free text is read as a comment, but not a word that looks like a misspelt keyword (a lost
  // declaration would shift every byte after it) and not bytes that are not text.
  expectInputError([&] { readPly("t.ply", replace(text, "element face 6", "elment face 6")); },
                   {"t.ply", "line 8", "'elment'", "misspelt 'element'"});
  expectInputError([&] { readPly("t.ply", replace(text, "property float x", "proprty float x")); },
                   {"t.ply", "line 5", "misspelt 'property'"});
  expectInputError(
      [&] { readPly("t.ply", replace(text, "end_header\n", "written by\x01\x02 tool\n")); },
      {"t.ply", "line 10", "not text"});
  // A missing end_header after free text says where the free text began.
  expectInputError(
      [&] { readPly("t.ply", text.substr(0, text.find("end_header")) + "Exported by SomeTool\n"); },
      {"t.ply", "no end_header line", "lines from 10 on were read as free text"});
  expectInputError(
      [&] { readPly("t.ply", replace(text, "end_header\n", "Exported by SomeTool\n")); },
      {"t.ply", "line 11", "data before end_header"});
  expectInputError([&] { readPly("t.ply", text.substr(0, text.find("end_header"))); },
                   {"t.ply", "no end_header line"});
  expectInputError(
      [&] {
        readPly("t.ply", replace(text, "property list uchar int", "property list float int"));
      },
      {"t.ply", "line 9", "must be an integer type"});
  expectInputError([&] { readPly("t.ply", replace(text, "property float z", "property float w")); },
                   {"t.ply", "line 4", "needs the properties x, y and z"});
  expectInputError([&] { readPly("t.ply", replace(text, "vertex_indices", "corners")); },
                   {"t.ply", "no faces"});
  expectInputError([&] { readPly("t.ply", replace(text, "\n4 0 2 3 1", "\n-4 0 2 3 1")); },
                   {"t.ply", "line 19", "negative"});
  expectInputError([&] { readPly("t.ply", replace(text, "\n4 0 2 3 1", "\n4 0 2 x 1")); },
                   {"t.ply", "line 19", "'x' is not an integer"});
}

// Every prefix of a valid file and every single-byte corruption must give a mesh or an
// InputError: never a crash, a hang, or another exception (run under the asan preset, this also
// checks that no byte outside the input is read).
TEST(PlyErrors, SurvivesEveryTruncationAndByteFlip) {
  std::vector<test::PlyElem> e = test::cubeElements("double", "uchar", "int");
  e[0].props.push_back({"float", "nx", ""});
  e[0].props.push_back({"int", "extra", "uchar"});
  for (auto& row : e[0].rows) {
    row.push_back({1});
    row.push_back({1, 2});
  }
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    const std::string file = test::writePly(e, format);
    int meshes = 0, errors = 0;
    auto attempt = [&](const std::string& bytes) {
      try {
        Mesh m = readPly("mutant.ply", bytes);
        m.validate();
        ++meshes;
      } catch (const InputError& err) {
        EXPECT_NE(std::string(err.what()).find("mutant.ply"), std::string::npos) << err.what();
        ++errors;
      }
    };
    for (size_t n = 0; n < file.size(); ++n) attempt(file.substr(0, n));
    for (size_t i = 0; i < file.size(); ++i)
      for (char mask : {'\x01', '\x80', '\xff'}) {
        std::string m = file;
        m[i] = char(m[i] ^ mask);
        attempt(m);
      }
    EXPECT_GT(meshes, 0) << format;  // some flips only change a coordinate
    EXPECT_GT(errors, int(file.size())) << format;
  }
}

}  // namespace
}  // namespace mirage
