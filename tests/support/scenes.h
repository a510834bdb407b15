// Small scenes built in code for tests.
#pragma once

#include "scene/builtin_scenes.h"
#include "scene/procedural.h"

namespace mirage::test {

// One mirror sphere under the procedural sky and nothing else: every reflected ray leaves the
// scene, so a light probe at infinity is exact.
inline Scene mirrorSphereInSky() {
  Scene s;
  s.name = "mirror-sphere-in-sky";
  int sphere = addMesh(s, procedural::sphere(1.0f, 128, 64));
  int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "sphere", sphere, mirror, {});
  CameraDesc c;
  c.position = {0.0f, 0.8f, 3.2f};
  c.target = {0.0f, 0.0f, 0.0f};
  c.fov_y_degrees = 50.0f;
  s.cameras.push_back(c);
  s.validate();
  return s;
}

}  // namespace mirage::test
