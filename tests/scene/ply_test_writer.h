// A small PLY writer for the tests: the same elements written as ASCII, binary little endian or
// binary big endian, so that every encoding is checked against the same expected mesh.
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

#include "scene/model_loader_files.h"

namespace mirage::test {

struct PlyProp {
  std::string type;  // scalar type, or a list's item type ("float", "int32", ...)
  std::string name;
  std::string count_type;  // non-empty: a list with this length type
};

struct PlyElem {
  std::string name;
  std::vector<PlyProp> props;
  // rows[i][p]: the values of property p of element i (one for a scalar, the items of a list).
  std::vector<std::vector<std::vector<double>>> rows;
};

inline void putTyped(Bytes& b, const std::string& t, double v) {
  if (t == "char" || t == "int8")
    b.put(int8_t(v));
  else if (t == "uchar" || t == "uint8")
    b.put(uint8_t(v));
  else if (t == "short" || t == "int16")
    b.put(int16_t(v));
  else if (t == "ushort" || t == "uint16")
    b.put(uint16_t(v));
  else if (t == "int" || t == "int32")
    b.put(int32_t(v));
  else if (t == "uint" || t == "uint32")
    b.put(uint32_t(v));
  else if (t == "float" || t == "float32")
    b.put(float(v));
  else if (t == "double" || t == "float64")
    b.put(double(v));
  else
    throw std::runtime_error("bad test type " + t);
}

// format: "ascii", "binary_little_endian" or "binary_big_endian".
inline std::string writePly(const std::vector<PlyElem>& elems, const std::string& format,
                            const std::string& extra_header = "") {
  std::string h =
      "ply\nformat " + format + " 1.0\ncomment written by the mirage tests\n" + extra_header;
  for (const PlyElem& e : elems) {
    h += fmt::format("element {} {}\n", e.name, e.rows.size());
    for (const PlyProp& p : e.props) {
      if (p.count_type.empty())
        h += fmt::format("property {} {}\n", p.type, p.name);
      else
        h += fmt::format("property list {} {} {}\n", p.count_type, p.type, p.name);
    }
  }
  h += "end_header\n";
  if (format == "ascii") {
    for (const PlyElem& e : elems)
      for (const auto& row : e.rows) {
        std::string line;
        for (size_t p = 0; p < row.size(); ++p) {
          if (!e.props[p].count_type.empty()) line += fmt::format("{} ", row[p].size());
          for (double v : row[p]) line += fmt::format("{} ", v);
        }
        line.back() = '\n';
        h += line;
      }
    return h;
  }
  Bytes b(format == "binary_big_endian");
  for (const PlyElem& e : elems)
    for (const auto& row : e.rows)
      for (size_t p = 0; p < row.size(); ++p) {
        if (!e.props[p].count_type.empty())
          putTyped(b, e.props[p].count_type, double(row[p].size()));
        for (double v : row[p]) putTyped(b, e.props[p].type, v);
      }
  return h + b.str();
}

// The unit cube [0,1]^3 as 8 vertices and 6 outward quads.
inline std::vector<std::vector<double>> cubeVertices() {
  std::vector<std::vector<double>> v;
  for (int i = 0; i < 8; ++i)
    v.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  return v;
}
inline std::vector<std::vector<double>> cubeQuads() {
  return {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
}

// The cube with x, y, z of `coord_type` and faces as a list of `count_type`/`index_type`.
inline std::vector<PlyElem> cubeElements(const std::string& coord_type = "float",
                                         const std::string& count_type = "uchar",
                                         const std::string& index_type = "int") {
  PlyElem v{"vertex", {{coord_type, "x", ""}, {coord_type, "y", ""}, {coord_type, "z", ""}}, {}};
  for (const auto& p : cubeVertices()) v.rows.push_back({{p[0]}, {p[1]}, {p[2]}});
  PlyElem f{"face", {{index_type, "vertex_indices", count_type}}, {}};
  for (const auto& q : cubeQuads()) f.rows.push_back({q});
  return {v, f};
}

}  // namespace mirage::test
