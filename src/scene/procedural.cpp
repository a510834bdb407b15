#include "scene/procedural.h"

#include "core/error.h"

namespace mirage::procedural {

namespace {

void finish(Mesh& mesh, const char* generator) {
  mesh.name = generator;
  mesh.source = std::string("builtin:") + generator;
  if (mesh.normals.size() != mesh.positions.size()) mesh.computeNormals();
  mesh.computeTangents();
}

// Adds a flat quad a-b-c-d (counter-clockwise seen from the front) with uv corners.
void addQuad(Mesh& m, vec3 a, vec3 b, vec3 c, vec3 d, vec2 uv_size) {
  uint32_t base = uint32_t(m.positions.size());
  vec3 n = glm::normalize(glm::cross(b - a, c - a));
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.normals.insert(m.normals.end(), {n, n, n, n});
  m.uvs.insert(m.uvs.end(), {{0, 0}, {uv_size.x, 0}, {uv_size.x, uv_size.y}, {0, uv_size.y}});
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base, base + 2, base + 3});
}

}  // namespace

Mesh sphere(float radius, int segments, int rings) {
  if (radius <= 0.0f || segments < 3 || rings < 2)
    throwInput("sphere: radius {} must be > 0, segments {} >= 3, rings {} >= 2", radius, segments,
               rings);
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    float v = float(r) / float(rings);
    float theta = v * kPi;
    for (int s = 0; s <= segments; ++s) {
      float u = float(s) / float(segments);
      float phi = u * 2.0f * kPi;
      vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      m.positions.push_back(radius * n);
      m.normals.push_back(n);
      m.uvs.push_back({u, 1.0f - v});
    }
  }
  uint32_t row = uint32_t(segments + 1);
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t i = uint32_t(r) * row + uint32_t(s);
      if (r != 0) m.triangles.push_back({i, i + row, i + 1});
      if (r != rings - 1) m.triangles.push_back({i + 1, i + row, i + row + 1});
    }
  finish(m, "sphere");
  return m;
}

Mesh box(const vec3& h, bool inward) {
  Mesh m;
  vec3 c[8];
  for (int i = 0; i < 8; ++i)
    c[i] = vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
  vec3 s = 2.0f * h;
  addQuad(m, c[4], c[5], c[7], c[6], {s.x, s.y});  // +Z
  addQuad(m, c[1], c[0], c[2], c[3], {s.x, s.y});  // -Z
  addQuad(m, c[5], c[1], c[3], c[7], {s.z, s.y});  // +X
  addQuad(m, c[0], c[4], c[6], c[2], {s.z, s.y});  // -X
  addQuad(m, c[6], c[7], c[3], c[2], {s.x, s.z});  // +Y
  addQuad(m, c[0], c[1], c[5], c[4], {s.x, s.z});  // -Y
  if (inward) {
    for (vec3& n : m.normals) n = -n;
    for (uvec3& t : m.triangles) std::swap(t.y, t.z);
  }
  finish(m, inward ? "room" : "box");
  return m;
}

Mesh quad(float width, float depth, float uv_per_unit, int cells_x, int cells_z) {
  if (cells_x < 1 || cells_z < 1 || cells_x > 4096 || cells_z > 4096)
    throwInput("quad: cells {}x{} must be in 1..4096 each", cells_x, cells_z);
  Mesh m;
  float x = 0.5f * width, z = 0.5f * depth;
  if (cells_x == 1 && cells_z == 1) {
    addQuad(m, {-x, 0, z}, {x, 0, z}, {x, 0, -z}, {-x, 0, -z},
            {width * uv_per_unit, depth * uv_per_unit});
    finish(m, "quad");
    return m;
  }
  // The same corners, orientation and uvs as the single quad, on a grid of shared vertices.
  for (int j = 0; j <= cells_z; ++j)
    for (int i = 0; i <= cells_x; ++i) {
      const float u = float(i) / float(cells_x), v = float(j) / float(cells_z);
      m.positions.push_back({-x + width * u, 0.0f, z - depth * v});
      m.normals.push_back({0.0f, 1.0f, 0.0f});
      m.uvs.push_back({width * uv_per_unit * u, depth * uv_per_unit * v});
    }
  const uint32_t row = uint32_t(cells_x + 1);
  for (uint32_t j = 0; j < uint32_t(cells_z); ++j)
    for (uint32_t i = 0; i < uint32_t(cells_x); ++i) {
      const uint32_t a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  finish(m, "quad");
  return m;
}

Mesh lathe(const std::vector<vec2>& profile, int segments) {
  if (profile.size() < 2 || segments < 3)
    throwInput("lathe: needs >= 2 profile points, >= 3 segments");
  Mesh m;
  for (size_t p = 0; p < profile.size(); ++p) {
    for (int s = 0; s <= segments; ++s) {
      float phi = 2.0f * kPi * float(s) / float(segments);
      m.positions.push_back(
          {profile[p].x * std::cos(phi), profile[p].y, -profile[p].x * std::sin(phi)});
      m.uvs.push_back({float(s) / float(segments), float(p) / float(profile.size() - 1)});
    }
  }
  uint32_t row = uint32_t(segments + 1);
  for (uint32_t p = 0; p + 1 < profile.size(); ++p)
    for (uint32_t s = 0; s < uint32_t(segments); ++s) {
      uint32_t i = p * row + s;
      m.triangles.push_back({i, i + 1, i + row});
      m.triangles.push_back({i + 1, i + row + 1, i + row});
    }
  // Drop triangles collapsed on the axis (radius 0 rows).
  std::erase_if(m.triangles, [&](const uvec3& t) {
    vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
    return glm::length(glm::cross(b - a, c - a)) < 1e-10f;
  });
  m.computeNormals();
  // The seam duplicates vertices; average their normals so the surface is smooth. On the axis
  // one of the two may be in no triangle (its normal a placeholder): it takes the other's.
  std::vector<bool> used(m.positions.size(), false);
  for (const uvec3& t : m.triangles) used[t.x] = used[t.y] = used[t.z] = true;
  for (size_t p = 0; p < profile.size(); ++p) {
    size_t a = p * row, b = a + size_t(segments);
    if (used[a] && used[b]) {
      vec3 sum = m.normals[a] + m.normals[b];
      if (glm::length(sum) > 1e-12f) m.normals[a] = m.normals[b] = glm::normalize(sum);
    } else if (used[a]) {
      m.normals[b] = m.normals[a];
    } else if (used[b]) {
      m.normals[a] = m.normals[b];
    }
  }
  finish(m, "lathe");
  return m;
}

Mesh cylinder(float radius, float height, int segments) {
  return lathe({{0.0f, 0.0f},
                {radius, 0.0f},
                {radius, 0.0f},
                {radius, height},
                {radius, height},
                {0.0f, height}},
               segments);
}

Mesh torus(float major_radius, float minor_radius, int segments, int sides) {
  Mesh m;
  for (int i = 0; i <= segments; ++i) {
    float u = 2.0f * kPi * float(i) / float(segments);
    vec3 center(major_radius * std::cos(u), major_radius * std::sin(u), 0.0f);
    for (int j = 0; j <= sides; ++j) {
      float v = 2.0f * kPi * float(j) / float(sides);
      vec3 n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
      m.positions.push_back(center + minor_radius * n);
      m.normals.push_back(n);
      m.uvs.push_back({float(i) / float(segments), float(j) / float(sides)});
    }
  }
  uint32_t row = uint32_t(sides + 1);
  for (uint32_t i = 0; i < uint32_t(segments); ++i)
    for (uint32_t j = 0; j < uint32_t(sides); ++j) {
      uint32_t a = i * row + j;
      m.triangles.push_back({a, a + row, a + 1});
      m.triangles.push_back({a + 1, a + row, a + row + 1});
    }
  finish(m, "torus");
  return m;
}

Mesh pyramid(float w, float height, bool inverted) {
  Mesh m;
  float apex_y = inverted ? 0.0f : height, base_y = inverted ? height : 0.0f;
  vec3 apex(0, apex_y, 0);
  vec3 b[4] = {{-w, base_y, w}, {w, base_y, w}, {w, base_y, -w}, {-w, base_y, -w}};
  for (int i = 0; i < 4; ++i) {
    vec3 p = b[i], q = b[(i + 1) % 4];
    vec3 n = glm::normalize(glm::cross(q - p, apex - p));
    if (inverted) n = -n;
    uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {p, q, apex});
    m.normals.insert(m.normals.end(), {n, n, n});
    m.uvs.insert(m.uvs.end(), {{0, 0}, {1, 0}, {0.5f, 1}});
    if (inverted)
      m.triangles.push_back({base, base + 2, base + 1});
    else
      m.triangles.push_back({base, base + 1, base + 2});
  }
  // The base (top face when inverted).
  uint32_t base = uint32_t(m.positions.size());
  vec3 n(0, inverted ? 1.0f : -1.0f, 0);
  m.positions.insert(m.positions.end(), {b[0], b[1], b[2], b[3]});
  m.normals.insert(m.normals.end(), {n, n, n, n});
  m.uvs.insert(m.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  if (inverted) {
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
  } else {
    m.triangles.push_back({base, base + 2, base + 1});
    m.triangles.push_back({base, base + 3, base + 2});
  }
  finish(m, "pyramid");
  return m;
}

Mesh teapotLike(int segments) {
  Mesh m;
  // Body: a squat bulb with a rim, like the Utah teapot's silhouette.
  std::vector<vec2> body = {{0.0f, 0.0f},   {0.36f, 0.0f},  {0.48f, 0.08f}, {0.56f, 0.22f},
                            {0.58f, 0.36f}, {0.54f, 0.50f}, {0.44f, 0.60f}, {0.36f, 0.64f},
                            {0.38f, 0.67f}, {0.30f, 0.68f}, {0.22f, 0.74f}, {0.08f, 0.80f},
                            {0.07f, 0.86f}, {0.10f, 0.90f}, {0.05f, 0.95f}, {0.0f, 0.96f}};
  append(m, lathe(body, segments));
  // Handle: part of a torus on the -X side.
  append(m, torus(0.2f, 0.045f, segments / 2, 12),
         glm::translate(mat4(1.0f), vec3(-0.58f, 0.34f, 0.0f)));
  // Spout: a tapered tube leaning out on the +X side.
  Mesh spout = lathe({{0.0f, 0.0f}, {0.09f, 0.0f}, {0.05f, 0.5f}, {0.0f, 0.5f}}, 16);
  mat4 t = glm::translate(mat4(1.0f), vec3(0.5f, 0.22f, 0.0f)) *
           glm::rotate(mat4(1.0f), radians(-50.0f), vec3(0, 0, 1));
  append(m, spout, t);
  finish(m, "teapot-like");
  return m;
}

void append(Mesh& mesh, Mesh part, const mat4& m) {
  part.transform(m);
  uint32_t base = uint32_t(mesh.positions.size());
  bool uvs = mesh.uvs.size() == mesh.positions.size() && part.uvs.size() == part.positions.size();
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
  if (uvs)
    mesh.uvs.insert(mesh.uvs.end(), part.uvs.begin(), part.uvs.end());
  else
    mesh.uvs.clear();
  mesh.tangents.clear();
  for (uvec3 t : part.triangles) mesh.triangles.push_back(t + uvec3(base));
}

}  // namespace mirage::procedural
