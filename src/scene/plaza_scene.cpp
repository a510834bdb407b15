// The built-in scene `plaza`: the scale case. 240 diffuse objects of five kinds (over a million
// triangles: the shapes finely tessellated, as scanned or modelled assets are) stand in a 16 x 15
// grid on a square, among 20 mirrors: 12 mirror spheres and 2 mirror teapots (curved) and 6
// upright planar panels facing the square from its edges. Every method must render it: billboards
// and depth maps per object and reflector exceed what a driver holds, which impostor groups and
// per-reflector candidate lists are for (docs/benchmarks.md, "Scale").
#include "scene/builtin_scene_parts.h"
#include "scene/procedural.h"

#include <fmt/format.h>

namespace mirage {

namespace {

constexpr int kColumns = 16, kRows = 15;
constexpr float kSpacing = 1.8f;

// A deterministic hash of a grid cell, so that the layout is the same on every machine.
uint32_t cellHash(int i) {
  uint32_t h = uint32_t(i) * 2654435761u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  return h ^ (h >> 15);
}

const vec3 kPalette[] = {{0.85f, 0.18f, 0.12f}, {0.2f, 0.7f, 0.25f},  {0.15f, 0.3f, 0.85f},
                         {0.9f, 0.8f, 0.15f},   {0.55f, 0.25f, 0.7f}, {0.95f, 0.5f, 0.1f},
                         {0.1f, 0.75f, 0.8f},   {0.85f, 0.85f, 0.8f}};

vec3 cellCentre(int column, int row) {
  return {kSpacing * (float(column) - 0.5f * float(kColumns - 1)), 0.0f,
          kSpacing * (float(row) - 0.5f * float(kRows - 1))};
}

// The five shapes, shared by the objects (one mesh each, many instances) and how each stands.
struct Shape {
  int mesh;
  float lift;  // how far its base lies below its origin, at size 1
  float size;  // its scale at the cell's size 1
};

std::vector<Shape> addShapes(Scene& s) {
  return {{addMesh(s, procedural::teapotLike(96)), 0.0f, 0.5f},
          {addMesh(s, procedural::torus(0.32f, 0.11f, 128, 48)), 0.43f, 1.0f},
          {addMesh(s, procedural::sphere(0.3f, 96, 48)), 0.3f, 1.0f},
          {addMesh(s, procedural::cylinder(0.18f, 1.1f, 96)), 0.0f, 1.0f},
          {addMesh(s, procedural::box(vec3(0.28f))), 0.28f, 1.0f}};
}

// The 240 diffuse objects, one per grid cell, of a shape, colour, size and turn of the cell's hash.
void addObjects(Scene& s) {
  const std::vector<Shape> shapes = addShapes(s);
  std::vector<int> materials;
  for (size_t c = 0; c < std::size(kPalette); ++c)
    materials.push_back(addMaterial(s, Material::diffuse(fmt::format("paint-{}", c), kPalette[c])));
  for (int row = 0; row < kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      const int i = row * kColumns + column;
      const uint32_t h = cellHash(i);
      const Shape& shape = shapes[h % shapes.size()];
      const float scale = shape.size * (0.7f + 0.1f * float((h >> 8) % 5));
      // (The torus is made standing, in the XY plane: it rests on its rim.)
      const Transform t = placeAt(cellCentre(column, row) + vec3(0.0f, shape.lift * scale, 0.0f),
                                  vec3(scale), rotationY(float((h >> 12) % 360)));
      addInstance(s, fmt::format("object-{}", i + 1), shape.mesh,
                  materials[(h >> 4) % materials.size()], t);
    }
}

// The 14 curved mirrors stand between the grid's cells (on the lines half a cell off), above
// the objects' tops where they bob; the 6 panels face the square from three of its edges.
void addMirrors(Scene& s) {
  const int chrome = addMaterial(s, Material::mirror("chrome"));
  const int sphere = addMesh(s, procedural::sphere(0.55f, 96, 48));
  int n = 0;
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      addInstance(s, fmt::format("mirror-sphere-{}", ++n), sphere, chrome,
                  placeAt(cellCentre(2 + 4 * column, 2 + 5 * row) +
                          vec3(0.5f * kSpacing, 1.6f, 0.5f * kSpacing)));
  const int silver = addMaterial(s, Material::mirror("silver", vec3(0.05f)));
  const int teapot = addMesh(s, procedural::teapotLike(96));
  addInstance(s, "mirror-teapot-1", teapot, silver,
              placeAt(cellCentre(4, 4) + vec3(0.9f, 1.3f, 0.9f), vec3(0.5f), rotationY(30)));
  addInstance(s, "mirror-teapot-2", teapot, silver,
              placeAt(cellCentre(11, 9) + vec3(0.9f, 1.3f, 0.9f), vec3(0.5f), rotationY(-60)));
  const int glass = addMaterial(s, Material::mirror("panel", vec3(0.05f)));
  const int panel = addMesh(s, procedural::quad(4.0f, 2.4f));
  const float half_x = 0.5f * kSpacing * float(kColumns) + 0.6f;
  const float half_z = 0.5f * kSpacing * float(kRows) + 0.6f;
  for (int k = 0; k < 3; ++k) {
    const float along = 7.0f * float(k - 1);
    // The back edge (facing +Z), then the left and right edges (facing +X and -X).
    addInstance(s, fmt::format("mirror-panel-back-{}", k + 1), panel, glass,
                placeAt({along, 1.3f, -half_z}, vec3(1.0f), rotationX(90.0f)));
    addInstance(s, fmt::format("mirror-panel-{}-{}", k % 2 ? "right" : "left", k + 1), panel, glass,
                placeAt({k % 2 ? half_x : -half_x, 1.3f, 0.6f * along}, vec3(1.0f),
                        rotationY(k % 2 ? -90.0f : 90.0f) * rotationX(90.0f)));
  }
}

}  // namespace

Scene plazaScene(const SceneOptions&) {
  Scene s;
  addObject(s, "floor", procedural::quad(40.0f, 40.0f, 1.0f),
            Material::checker("checker", kCheckerLight, kCheckerDark, 1.0f), {});
  addObjects(s);
  addMirrors(s);
  addMainCamera(s, {0.0f, 11.0f, 19.5f}, {0.0f, 0.0f, -1.0f}, 62.0f);
  return s;
}

}  // namespace mirage
