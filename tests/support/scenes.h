// Small scenes built in code for tests.
#pragma once

#include <cmath>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/procedural.h"

namespace mirage::test {

// The index of the instance called `name`, or -1.
inline int instanceNamed(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == name) return int(i);
  return -1;
}

// Adds a camera at `position` looking at `target`, then validates the scene.
inline void finishScene(Scene& s, vec3 position, vec3 target, float fov_y_degrees) {
  CameraDesc c;
  c.position = position;
  c.target = target;
  c.fov_y_degrees = fov_y_degrees;
  s.cameras.push_back(c);
  s.validate();
}

// teapot-sphere without its floor: the reflector pixels show the sky and the two objects, so
// that the objects' reflections carry the error (a background cube map is exact for the sky).
inline Scene teapotSphereObjectsOnly() {
  Scene scene = makeBuiltinScene("teapot-sphere");
  scene.instances.erase(scene.instances.begin());  // the floor comes first
  return scene;
}

// One mirror sphere under the procedural sky and nothing else: every reflected ray leaves the
// scene, so a light probe at infinity is exact.
inline Scene mirrorSphereInSky() {
  Scene s;
  s.name = "mirror-sphere-in-sky";
  int sphere = addMesh(s, procedural::sphere(1.0f, 128, 64));
  int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "sphere", sphere, mirror, {});
  finishScene(s, vec3{0.0f, 0.8f, 3.2f}, vec3{0.0f, 0.0f, 0.0f}, 50.0f);
  return s;
}

// A mirror sphere off-centre in an empty, closed checker room: the room is its own box proxy, so
// a probe at the sphere's centre looked up through that box sees exactly what each reflected ray
// reaches (envmap-box is exact here but for texture sampling).
inline Scene mirrorSphereInRoom() {
  Scene s;
  s.name = "mirror-sphere-in-room";
  int room = addMesh(s, procedural::box({3.0f, 2.0f, 3.0f}, true));
  int walls = addMaterial(s, Material::checker("walls", kCheckerLight, {0.25f, 0.35f, 0.6f}, 1.0f));
  addInstance(s, "room", room, walls, placeAt({0.0f, 2.0f, 0.0f}));
  int sphere = addMesh(s, procedural::sphere(0.7f, 128, 64));
  int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "sphere", sphere, mirror, placeAt({0.8f, 1.2f, -0.6f}));
  finishScene(s, vec3{-1.5f, 2.2f, 2.4f}, vec3{0.8f, 1.2f, -0.6f}, 50.0f);
  return s;
}

// Two mirror spheres and a box over a checker floor (a planar object): a small scene for the
// billboard placement rules. `floor_only` leaves out the box and the second sphere.
inline Scene spheresOverFloor(bool floor_only = false) {
  Scene s;
  s.name = "spheres-over-floor";
  int floor = addMesh(s, procedural::quad(8.0f, 8.0f));
  int checker = addMaterial(s, Material::checker("floor", kCheckerLight, kCheckerDark, 1.0f));
  addInstance(s, "floor", floor, checker, {});
  int sphere = addMesh(s, procedural::sphere(0.8f, 128, 64));
  int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "sphere-a", sphere, mirror, placeAt({0.0f, 1.0f, 0.0f}));
  if (!floor_only) {
    addInstance(s, "sphere-b", sphere, mirror, placeAt({2.2f, 1.0f, -0.5f}));
    addBox(s, "box", {-1.8f, 0.5f, 0.6f}, vec3(0.5f), {0.85f, 0.2f, 0.15f}, 20.0f);
  }
  finishScene(s, vec3{0.5f, 2.6f, 5.0f}, vec3{0.5f, 0.8f, 0.0f}, 45.0f);
  return s;
}

// A mirror sphere above a ring of `count` small diffuse spheres and cubes (alternating) over
// nothing but the sky: the many-objects case of impostor groups, small enough to ray trace.
inline Scene mirrorAmongObjects(int count) {
  Scene s;
  s.name = "mirror-among-objects";
  const int ball = addMesh(s, procedural::sphere(0.16f, 32, 16));
  const int cube = addMesh(s, procedural::box(vec3(0.13f)));
  const int red = addMaterial(s, Material::diffuse("red", {0.85f, 0.2f, 0.15f}));
  const int blue = addMaterial(s, Material::diffuse("blue", {0.2f, 0.35f, 0.85f}));
  for (int k = 0; k < count; ++k) {
    const float angle = 6.2831853f * float(k) / float(count);
    const float radius = 1.6f + 0.5f * float(k % 3);
    addInstance(
        s, "object-" + std::to_string(k + 1), k % 2 ? cube : ball, k % 4 < 2 ? red : blue,
        placeAt({radius * std::cos(angle), 0.25f * float(k % 2), radius * std::sin(angle)}));
  }
  const int sphere = addMesh(s, procedural::sphere(0.6f, 96, 48));
  addInstance(s, "mirror", sphere, addMaterial(s, Material::mirror("mirror")),
              placeAt({0.0f, 0.7f, 0.0f}));
  finishScene(s, vec3{0.0f, 2.4f, 3.4f}, vec3{0.0f, 0.5f, 0.0f}, 45.0f);
  return s;
}

// An upright two-sided mirror (3 x 2, in the plane z = 0) over a floor, a box and a ball on each
// side of it and a mirror sphere in front: the case of a planar reflector's lists per side.
inline Scene mirrorWallBetweenObjects() {
  Scene s;
  s.name = "mirror-wall-between-objects";
  const int floor = addMesh(s, procedural::quad(10.0f, 10.0f));
  addInstance(s, "floor", floor,
              addMaterial(s, Material::checker("floor", kCheckerLight, kCheckerDark, 1.0f)), {});
  const int wall = addMesh(s, procedural::quad(3.0f, 2.0f));
  const int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "wall", wall, mirror,
              placeAt({0.0f, 1.2f, 0.0f}, vec3(1.0f),
                      glm::angleAxis(glm::radians(90.0f), vec3(1.0f, 0.0f, 0.0f))));
  const int ball = addMesh(s, procedural::sphere(0.35f, 32, 16));
  const int red = addMaterial(s, Material::diffuse("red", {0.85f, 0.2f, 0.15f}));
  const int blue = addMaterial(s, Material::diffuse("blue", {0.2f, 0.35f, 0.85f}));
  addBox(s, "box-front", {-0.8f, 0.4f, 1.6f}, vec3(0.4f), {0.2f, 0.75f, 0.3f}, 20.0f);
  addInstance(s, "ball-front", ball, red, placeAt({0.9f, 0.35f, 1.4f}));
  addBox(s, "box-back", {0.8f, 0.4f, -1.6f}, vec3(0.4f), {0.9f, 0.8f, 0.2f}, 20.0f);
  addInstance(s, "ball-back", ball, blue, placeAt({-0.9f, 0.35f, -1.4f}));
  addInstance(s, "sphere", addMesh(s, procedural::sphere(0.4f, 64, 32)), mirror,
              placeAt({1.9f, 0.6f, 2.2f}));
  finishScene(s, vec3{2.6f, 2.2f, 5.0f}, vec3{0.0f, 1.0f, 0.0f}, 50.0f);
  return s;
}

}  // namespace mirage::test
