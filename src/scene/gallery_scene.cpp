// The built-in scene `gallery`: one room holding every kind of reflector the methods favour
// differently, for choosing a technique per reflector (README, "Scenes"). The two planar wall
// mirrors are exact with `planar`, the sphere and the teapot near diffuse objects suit depth maps
// or billboards, the concave mirror reflects the room upside down, and the room is a box, which
// `envmap-box` models. Eleven diffuse objects of different sizes stand between them.
#include "scene/builtin_scene_parts.h"
#include "scene/procedural.h"

namespace mirage {

namespace {

// The room (8 x 4 x 8, checkered walls, y = 0 its floor) and its two wall mirrors: one on the
// back wall (z = -4) and one on the left (x = -4), both facing into the room.
void addRoomAndWallMirrors(Scene& s) {
  addObject(s, "room", procedural::box({4.0f, 2.0f, 4.0f}, true),
            Material::checker("walls", kCheckerLight, {0.3f, 0.42f, 0.35f}, 1.0f),
            placeAt({0.0f, 2.0f, 0.0f}));
  const int mirror = addMaterial(s, Material::mirror("wall-mirror", vec3(0.05f)));
  addInstance(s, "mirror-back", addMesh(s, procedural::quad(3.2f, 2.2f)), mirror,
              placeAt({-1.0f, 1.8f, -3.97f}, vec3(1.0f), rotationX(90.0f)));
  // The quad's normal +Y turned to +X: its width runs along y, its depth along z.
  addInstance(s, "mirror-left", addMesh(s, procedural::quad(2.2f, 3.6f)), mirror,
              placeAt({-3.97f, 1.8f, 0.2f}, vec3(1.0f), rotationZ(-90.0f)));
}

// The curved reflectors: a sphere, a teapot-like object and a concave dish on the back wall.
void addCurvedMirrors(Scene& s) {
  addObject(s, "mirror-sphere", procedural::sphere(0.6f, 96, 48), Material::mirror("chrome"),
            placeAt({1.5f, 0.6f, -1.3f}));
  addObject(s, "mirror-teapot", procedural::teapotLike(), Material::mirror("silver", vec3(0.05f)),
            placeAt({-1.6f, 0.0f, 0.5f}, vec3(0.9f), rotationY(35.0f)));
  // A spherical cap (rim at 45 degrees), its inside facing the room.
  addObject(s, "concave-mirror", procedural::lathe(capProfile(45.0f, 8), 48),
            Material::mirror("dish"), placeAt({2.5f, 1.6f, -3.6f}, vec3(0.9f), rotationX(90.0f)));
}

// Eleven diffuse objects, from a 0.12 ball to a 2.6 column.
void addDiffuseObjects(Scene& s) {
  addBox(s, "red-box", {2.7f, 0.5f, 1.4f}, vec3(0.5f), {0.85f, 0.18f, 0.12f}, 20.0f);
  addBox(s, "green-box", {-0.3f, 0.2f, 1.7f}, vec3(0.2f), {0.2f, 0.7f, 0.25f}, -15.0f);
  addBox(s, "blue-box", {-2.7f, 0.7f, -2.3f}, {0.35f, 0.7f, 0.35f}, {0.15f, 0.3f, 0.85f}, 30.0f);
  addBox(s, "cyan-box", {-3.1f, 0.25f, 2.6f}, vec3(0.25f), {0.1f, 0.75f, 0.8f}, 10.0f);
  addObject(s, "orange-column", procedural::cylinder(0.2f, 1.8f),
            Material::diffuse("orange", {0.95f, 0.5f, 0.1f}), placeAt({0.4f, 0.0f, -2.6f}));
  addObject(s, "white-column", procedural::cylinder(0.12f, 2.6f),
            Material::diffuse("white", {0.85f, 0.85f, 0.8f}), placeAt({3.3f, 0.0f, -1.9f}));
  addObject(s, "purple-teapot", procedural::teapotLike(),
            Material::diffuse("purple", {0.55f, 0.25f, 0.7f}),
            placeAt({0.2f, 0.0f, -0.6f}, vec3(0.6f), rotationY(-40.0f)));
  Transform standing = placeAt({2.1f, 0.47f, 0.2f});
  standing.rotation = glm::angleAxis(radians(80.0f), vec3(0, 1, 0)) * rotationX(90.0f);
  addObject(s, "yellow-torus", procedural::torus(0.35f, 0.12f, 64, 24),
            Material::diffuse("yellow", {0.9f, 0.8f, 0.15f}), standing);
  addObject(s, "green-ball", procedural::sphere(0.25f, 48, 24),
            Material::diffuse("green", {0.25f, 0.65f, 0.3f}), placeAt({-0.9f, 0.25f, -1.3f}));
  addObject(s, "red-ball", procedural::sphere(0.12f, 32, 16),
            Material::diffuse("red", {0.9f, 0.2f, 0.2f}), placeAt({1.0f, 0.12f, 1.0f}));
  addObject(s, "stone-pyramid", procedural::pyramid(0.4f, 0.8f, false),
            Material::diffuse("stone", {0.75f, 0.72f, 0.65f}), placeAt({-2.5f, 0.0f, 1.6f}));
}

}  // namespace

Scene galleryScene(const SceneOptions&) {
  Scene s;
  addRoomAndWallMirrors(s);
  addCurvedMirrors(s);
  addDiffuseObjects(s);
  addMainCamera(s, {1.2f, 2.3f, 3.7f}, {-0.6f, 1.0f, -1.6f}, 62.0f);
  // Eight seconds through the room, from the right front corner to the left, keeping the
  // mirrors in view.
  addWalkCamera(s,
                {{0.0f, {3.2f, 1.8f, 3.4f}, {-1.0f, 1.2f, -2.5f}},
                 {2.5f, {1.4f, 1.7f, 2.6f}, {-2.0f, 1.1f, -1.5f}},
                 {5.0f, {-0.4f, 1.75f, 2.8f}, {-1.5f, 1.0f, -3.0f}},
                 {8.0f, {0.6f, 1.8f, 3.3f}, {2.2f, 1.2f, -3.0f}}},
                62.0f);
  // What the single methods measured best per reflector (docs/quality.md, "gallery"): the wall
  // mirrors exact by re-rendering, the curved ones through box-projected probes. `mirage advise`
  // chooses within a frame budget instead.
  s.reflections = {{{"mirror-back", "mirror-left"}, "planar", {}, "gallery: reflections[0]"},
                   {{"*"}, "envmap-box", {}, "gallery: reflections[1]"}};
  return s;
}

}  // namespace mirage
