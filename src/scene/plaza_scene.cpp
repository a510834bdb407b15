// The built-in scene `plaza`: the scale case. 240 diffuse objects of five kinds (over a million
// triangles: the shapes finely tessellated, as scanned or modelled assets are) stand in a 16 x 15
// grid on a square, among 20 mirrors: 12 mirror spheres and 2 mirror teapots (curved) and 6
// upright planar panels facing the square from its edges. Every method must render it: billboards
// and depth maps per object and reflector exceed what a driver holds, which impostor groups are
// for (docs/benchmarks.md, "Scale").
//
// For the scaling sweeps, `--objects N` (10..1000) lays out N objects on a grid of the same
// spacing and aspect at the square's centre (the square and its mirrors grow past 240), and
// `--reflectors N` (1..32) keeps the first N mirrors: the 20 above, then 12 more spheres on a
// second lattice. At the defaults the scene is the one the figures use.
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/builtin_scene_parts.h"
#include "scene/procedural.h"

#include <fmt/format.h>

namespace mirage {

namespace {

constexpr int kDefaultObjects = 240, kMaxObjects = 1000, kMinObjects = 10;
constexpr int kDefaultMirrors = 20, kMaxMirrors = 32;
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

// The grid of cells: 16 x 15 for the default 240 objects, the same aspect for other counts.
struct Grid {
  int columns = 16, rows = 15;

  explicit Grid(int objects) {
    columns = std::max(1, int(std::lround(std::sqrt(double(objects) * 16.0 / 15.0))));
    rows = (objects + columns - 1) / columns;
  }
  vec3 centre(int column, int row) const {
    return {kSpacing * (float(column) - 0.5f * float(columns - 1)), 0.0f,
            kSpacing * (float(row) - 0.5f * float(rows - 1))};
  }
  // The cell at (column, row) of the default 16 x 15 grid, scaled to this one.
  vec3 scaled(float column, float row) const {
    return centre(int(std::lround(column * float(columns) / 16.0f)),
                  int(std::lround(row * float(rows) / 15.0f)));
  }
  // How much larger than the default grid this one is.
  float scale() const { return std::max(float(columns) / 16.0f, float(rows) / 15.0f); }
};

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

// The diffuse objects, one per grid cell, of a shape, colour, size and turn of the cell's hash:
// a block of cells of the square's grid at its centre (the whole grid from 240 objects up), so
// that the objects keep clear of the mirrors' lattice.
void addObjects(Scene& s, const Grid& square, int count) {
  const Grid block(count);
  const int first_column = std::max(0, (square.columns - block.columns) / 2);
  const int first_row = std::max(0, (square.rows - block.rows) / 2);
  const std::vector<Shape> shapes = addShapes(s);
  std::vector<int> materials;
  for (size_t c = 0; c < std::size(kPalette); ++c)
    materials.push_back(addMaterial(s, Material::diffuse(fmt::format("paint-{}", c), kPalette[c])));
  for (int i = 0; i < count; ++i) {
    const int column = first_column + i % block.columns, row = first_row + i / block.columns;
    const uint32_t h = cellHash(i);
    const Shape& shape = shapes[h % shapes.size()];
    const float scale = shape.size * (0.7f + 0.1f * float((h >> 8) % 5));
    // (The torus is made standing, in the XY plane: it rests on its rim.)
    const Transform t = placeAt(square.centre(column, row) + vec3(0.0f, shape.lift * scale, 0.0f),
                                vec3(scale), rotationY(float((h >> 12) % 360)));
    addInstance(s, fmt::format("object-{}", i + 1), shape.mesh,
                materials[(h >> 4) % materials.size()], t);
  }
}

// The mirrors in order: 12 spheres and 2 teapots (curved), standing between the grid's cells
// (on the lines half a cell off) above the objects' tops; 6 panels facing the square from three
// of its edges; then 12 more spheres on a second lattice. The first `count` are added.
void addMirrors(Scene& s, const Grid& grid, int count) {
  const int chrome = addMaterial(s, Material::mirror("chrome"));
  const int sphere = addMesh(s, procedural::sphere(0.55f, 96, 48));
  const vec3 above(0.5f * kSpacing, 1.6f, 0.5f * kSpacing);
  int n = 0;
  for (int row = 0; row < 3 && n < count; ++row)
    for (int column = 0; column < 4 && n < count; ++column)
      addInstance(s, fmt::format("mirror-sphere-{}", ++n), sphere, chrome,
                  placeAt(grid.scaled(float(2 + 4 * column), float(2 + 5 * row)) + above));
  const int silver = addMaterial(s, Material::mirror("silver", vec3(0.05f)));
  const int teapot = addMesh(s, procedural::teapotLike(96));
  const vec3 lift(0.9f, 1.3f, 0.9f);
  if (n++ < count)
    addInstance(s, "mirror-teapot-1", teapot, silver,
                placeAt(grid.scaled(4, 4) + lift, vec3(0.5f), rotationY(30)));
  if (n++ < count)
    addInstance(s, "mirror-teapot-2", teapot, silver,
                placeAt(grid.scaled(11, 9) + lift, vec3(0.5f), rotationY(-60)));
  const int glass = addMaterial(s, Material::mirror("panel", vec3(0.05f)));
  const int panel = addMesh(s, procedural::quad(4.0f, 2.4f));
  const float half_x = 0.5f * kSpacing * float(grid.columns) + 0.6f;
  const float half_z = 0.5f * kSpacing * float(grid.rows) + 0.6f;
  for (int k = 0; k < 3 && n < count; ++k) {
    const float along = 7.0f * float(k - 1) * float(grid.columns) / 16.0f;
    const float across = 0.6f * 7.0f * float(k - 1) * float(grid.rows) / 15.0f;
    // The back edge (facing +Z), then the left and right edges (facing +X and -X).
    if (n++ < count)
      addInstance(s, fmt::format("mirror-panel-back-{}", k + 1), panel, glass,
                  placeAt({along, 1.3f, -half_z}, vec3(1.0f), rotationX(90.0f)));
    if (n++ < count)
      addInstance(s, fmt::format("mirror-panel-{}-{}", k % 2 ? "right" : "left", k + 1), panel,
                  glass,
                  placeAt({k % 2 ? half_x : -half_x, 1.3f, across}, vec3(1.0f),
                          rotationY(k % 2 ? -90.0f : 90.0f) * rotationX(90.0f)));
  }
  for (int row = 0; row < 3 && n < count; ++row)
    for (int column = 0; column < 4 && n < count; ++column, ++n)
      addInstance(s, fmt::format("mirror-sphere-{}", n - 7), sphere, chrome,
                  placeAt(grid.scaled(float(4 * column), float(5 * row)) + above));
}

}  // namespace

Scene plazaScene(const SceneOptions& options) {
  const int objects = options.objects < 0 ? kDefaultObjects : options.objects;
  if (objects < kMinObjects || objects > kMaxObjects)
    throwInput("plaza: --objects {} is outside the allowed range {}..{}", objects, kMinObjects,
               kMaxObjects);
  const int mirrors = options.reflectors < 0 ? kDefaultMirrors : options.reflectors;
  if (mirrors < 1 || mirrors > kMaxMirrors)
    throwInput("plaza: --reflectors {} is outside the allowed range 1..{}", mirrors, kMaxMirrors);
  // The square holds the default 240 cells, or more for more objects.
  const Grid grid(std::max(objects, kDefaultObjects));
  Scene s;
  addObject(s, "floor", procedural::quad(40.0f * grid.scale(), 40.0f * grid.scale(), 1.0f),
            Material::checker("checker", kCheckerLight, kCheckerDark, 1.0f), {});
  addObjects(s, grid, objects);
  addMirrors(s, grid, mirrors);
  addMainCamera(s, vec3(0.0f, 11.0f, 19.5f) * grid.scale(), {0.0f, 0.0f, -1.0f}, 62.0f);
  return s;
}

}  // namespace mirage
