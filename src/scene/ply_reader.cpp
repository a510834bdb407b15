// mirage's own PLY reader: the papers' models (Stanford bunny, dragon, ...) come as PLY, often
// gzip-compressed ASCII. The header is parsed and checked first (ply_header.cpp); the data is
// then read by one of the readers of ply_data.h through the element loops below.
#include <algorithm>
#include <bit>
#include <type_traits>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "scene/gunzip.h"
#include "scene/loader_support.h"
#include "scene/model_loader.h"
#include "scene/ply_data.h"
#include "scene/ply_header.h"

namespace mirage {

namespace {

using ply::Element;
using ply::Format;
using ply::Header;
using ply::Position;
using ply::Property;

// Where each vertex property goes.
enum Slot { kX, kY, kZ, kNx, kNy, kNz, kU, kV, kSlotCount };

struct VertexLayout {
  std::vector<int> slot;  // per property: a Slot, or -1 (skipped)
  bool normals = false, uvs = false;
};

int slotOf(std::string_view n) {
  if (n == "x") return kX;
  if (n == "y") return kY;
  if (n == "z") return kZ;
  if (n == "nx") return kNx;
  if (n == "ny") return kNy;
  if (n == "nz") return kNz;
  if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s") return kU;
  if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t") return kV;
  return -1;
}

VertexLayout vertexLayout(const std::string& name, const Element& e) {
  VertexLayout layout;
  bool seen[kSlotCount] = {};
  for (const Property& p : e.properties) {
    int s = slotOf(p.name);
    if (s >= 0 && p.is_list)
      throwInput("{}: line {}: vertex property {} is a list; it must be a number", name, e.line,
                 p.name);
    // A second u/s-style name for the same slot is read as an unknown property.
    if (s >= 0 && seen[s]) s = -1;
    if (s >= 0) seen[s] = true;
    layout.slot.push_back(s);
  }
  if (!seen[kX] || !seen[kY] || !seen[kZ])
    throwInput("{}: line {}: element vertex needs the properties x, y and z", name, e.line);
  for (int& s : layout.slot) {
    // Half a normal or half a texture coordinate is ignored, as if absent.
    if ((s == kNx || s == kNy || s == kNz) && !(seen[kNx] && seen[kNy] && seen[kNz])) s = -1;
    if ((s == kU || s == kV) && !(seen[kU] && seen[kV])) s = -1;
  }
  layout.normals = seen[kNx] && seen[kNy] && seen[kNz];
  layout.uvs = seen[kU] && seen[kV];
  return layout;
}

// The face list: vertex_indices, or vertex_index as some writers call it.
int faceList(const Element& e) {
  for (const char* n : {"vertex_indices", "vertex_index"}) {
    int i = e.find(n);
    if (i >= 0 && e.properties[size_t(i)].is_list) return i;
  }
  return -1;
}

template <typename R>
void skipElements(R& r, Position& at, const Element& e) {
  if (e.properties.empty()) return;
  if constexpr (!std::is_same_v<R, ply::AsciiReader>) {
    bool fixed = std::none_of(e.properties.begin(), e.properties.end(),
                              [](const Property& p) { return p.is_list; });
    if (fixed) {
      // The header check guarantees count * size fits in the data.
      r.skipBytes(e.count * e.minBytes(Format::kBinaryLittleEndian));
      return;
    }
  }
  for (at.index = 0; at.index < e.count; ++at.index) {
    r.beginElement();
    for (const Property& p : e.properties) {
      if (p.is_list)
        r.skipList(p.count_type, p.type);
      else
        r.skip(p.type);
    }
    r.endElement();
  }
}

template <typename R>
void readVertices(R& r, Position& at, const Element& e, const VertexLayout& layout, Mesh& m) {
  m.positions.resize(size_t(e.count));
  if (layout.normals) m.normals.resize(size_t(e.count));
  if (layout.uvs) m.uvs.resize(size_t(e.count));
  double v[kSlotCount] = {};
  const size_t n = e.properties.size();
  for (at.index = 0; at.index < e.count; ++at.index) {
    r.beginElement();
    for (size_t j = 0; j < n; ++j) {
      const Property& p = e.properties[j];
      if (layout.slot[j] >= 0)
        v[layout.slot[j]] = r.real(p.type);
      else if (p.is_list)
        r.skipList(p.count_type, p.type);
      else
        r.skip(p.type);
    }
    r.endElement();
    vec3 pos{float(v[kX]), float(v[kY]), float(v[kZ])};
    if (!isFinite(pos))
      r.fail(fmt::format("has a non-finite position ({}, {}, {})", v[kX], v[kY], v[kZ]));
    size_t i = size_t(at.index);
    m.positions[i] = pos;
    if (layout.normals) m.normals[i] = vec3(float(v[kNx]), float(v[kNy]), float(v[kNz]));
    if (layout.uvs) m.uvs[i] = vec2(float(v[kU]), float(v[kV]));
  }
}

// Faces (polygons, fan-triangulated) or triangle strips (-1 restarts a strip).
template <typename R>
void readFaces(R& r, Position& at, const Element& e, int list, uint64_t vertex_count, bool strips,
               const LoadLimits& limits, Mesh& m) {
  std::vector<uint32_t> idx;
  const Property& lp = e.properties[size_t(list)];
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (m.triangles.size() >= limits.max_triangles)
      r.fail(fmt::format("makes more than {} triangles (LoadLimits::max_triangles)",
                         limits.max_triangles));
    m.triangles.push_back({a, b, c});
  };
  for (at.index = 0; at.index < e.count; ++at.index) {
    r.beginElement();
    for (size_t j = 0; j < e.properties.size(); ++j) {
      const Property& p = e.properties[j];
      if (int(j) != list) {
        if (p.is_list)
          r.skipList(p.count_type, p.type);
        else
          r.skip(p.type);
        continue;
      }
      int64_t n = r.count(p.count_type);
      idx.clear();
      for (int64_t k = 0; k < n; ++k) {
        int64_t i = r.integer(lp.type);
        if (strips && i == -1) {
          idx.push_back(UINT32_MAX);
          continue;
        }
        if (i < 0 || uint64_t(i) >= vertex_count)
          r.fail(fmt::format("refers to vertex {}, outside 0..{} (the vertex count is {})", i,
                             int64_t(vertex_count) - 1, vertex_count));
        idx.push_back(uint32_t(i));
      }
    }
    r.endElement();
    if (!strips) {
      for (size_t k = 2; k < idx.size(); ++k) add(idx[0], idx[k - 1], idx[k]);
      continue;
    }
    size_t start = 0;  // first index of the current strip
    for (size_t k = 0; k < idx.size(); ++k) {
      if (idx[k] == UINT32_MAX) {
        start = k + 1;
        continue;
      }
      if (k < start + 2) continue;
      uint32_t a = idx[k - 2], b = idx[k - 1], c = idx[k];
      if (a == b || b == c || a == c) continue;  // strips use degenerate triangles as joints
      if ((k - start) % 2 == 0)
        add(a, b, c);
      else
        add(b, a, c);
    }
  }
}

// The elements the mesh comes from, chosen and checked against the limits before reading.
struct Plan {
  const Element* vertices = nullptr;
  VertexLayout layout;
  const Element* faces = nullptr;
  int list = -1;  // the index list property of `faces`
};

Plan plan(const std::string& name, const Header& h, const LoadLimits& limits) {
  Plan p;
  p.vertices = h.find("vertex");
  if (!p.vertices) throwInput("{}: the PLY header declares no 'vertex' element", name);
  p.layout = vertexLayout(name, *p.vertices);
  for (const char* n : {"face", "tristrips"}) {
    const Element* e = h.find(n);
    if (e && faceList(*e) >= 0) {
      p.faces = e;
      p.list = faceList(*e);
      break;
    }
  }
  if (!p.faces)
    throwInput(
        "{}: no faces: the PLY header declares no 'face' element with a vertex_indices "
        "list (a point cloud cannot be rendered)",
        name);
  if (p.vertices->count > limits.max_vertices)
    throwInput(
        "{}: line {}: element vertex has {} vertices; at most {} are allowed "
        "(LoadLimits::max_vertices)",
        name, p.vertices->line, p.vertices->count, limits.max_vertices);
  if (p.faces->name == "face" && p.faces->count > limits.max_triangles)
    throwInput(
        "{}: line {}: element face has {} faces; at most {} triangles are allowed "
        "(LoadLimits::max_triangles)",
        name, p.faces->line, p.faces->count, limits.max_triangles);
  // A face makes at least one triangle: the header's counts bound what reading will allocate.
  checkAllocation(name,
                  fmt::format("line {}: {} vertices and {} faces", p.faces->line, p.vertices->count,
                              p.faces->count),
                  loader::meshBytes(p.vertices->count, p.faces->count), limits.max_bytes);
  return p;
}

template <typename R>
Mesh readData(R& r, Position& at, const Header& h, const Plan& p, const LoadLimits& limits) {
  const std::string& name = *at.file;
  const Element* vertices = p.vertices;
  const Element* faces = p.faces;
  Mesh m;
  m.name = loader::fileStem(name);
  m.source = name;
  if (faces->name == "face") m.triangles.reserve(size_t(faces->count));
  for (const Element& e : h.elements) {
    at.element = &e;
    if (&e == vertices)
      readVertices(r, at, e, p.layout, m);
    else if (&e == faces)
      readFaces(r, at, e, p.list, vertices->count, e.name == "tristrips", limits, m);
    else
      skipElements(r, at, e);
  }
  if constexpr (std::is_same_v<R, ply::AsciiReader>) {
    if (!r.atEnd())
      throwInput(
          "{}: line {}: unexpected data after the last element (are the header's element "
          "counts too small?)",
          name, r.line());
  } else {
    if (r.remaining() > 0)
      spdlog::warn("{}: {} bytes after the last element ignored", name, r.remaining());
  }
  if (m.triangles.empty())
    throwInput("{}: no triangles: the {} faces all have fewer than 3 vertices", name, faces->count);
  if (p.layout.normals) {
    if (loader::repairNormals(m))
      spdlog::warn("{}: some vertex normals are zero or not finite; all were recomputed", name);
  } else {
    m.computeNormals();
  }
  return m;
}

Mesh parsePly(const std::string& name, std::string_view data, const LoadLimits& limits) {
  Header h = ply::parseHeader(name, data);
  for (const std::string& warning : h.warnings) spdlog::warn("{}", warning);
  Plan p = plan(name, h, limits);
  ply::checkDataSize(name, h, data.size());
  if (p.vertices->count > UINT32_MAX)  // only reachable with the limits lifted
    throwInput("{}: line {}: element vertex has {} vertices; 32-bit indices reach {} at most", name,
               p.vertices->line, p.vertices->count, uint64_t(UINT32_MAX) + 1);
  Position at{&name, nullptr, 0};
  bool swap =
      (h.format == Format::kBinaryBigEndian) == (std::endian::native == std::endian::little);
  if (h.format == Format::kAscii) {
    ply::AsciiReader r(at, data.substr(h.data_offset), h.data_line);
    return readData(r, at, h, p, limits);
  }
  if (swap) {
    ply::BinaryReader<true> r(at, data, h.data_offset);
    return readData(r, at, h, p, limits);
  }
  ply::BinaryReader<false> r(at, data, h.data_offset);
  return readData(r, at, h, p, limits);
}

}  // namespace

Mesh readPly(const std::string& name, const std::string& bytes, const LoadLimits& limits) {
  if (isGzip(bytes)) return parsePly(name, gunzip(name, bytes, limits.max_bytes), limits);
  return parsePly(name, bytes, limits);
}

Mesh loadPly(const std::string& path, const LoadLimits& limits) {
  return readPly(path, loader::readWholeFile(path), limits);
}

}  // namespace mirage
