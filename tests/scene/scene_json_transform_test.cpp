// JSON scene files, what the fields mean: keyframed animation, Euler angles, `fit`, and model
// instances give the documented transforms and bounds.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

Scene parseIn(const fs::path& dir, const std::string& text) {
  writeText(dir / "box.ply", boxPlyText({1, 2, 3}, {5, 4, 4}));  // extent 4 x 2 x 1
  std::ofstream(dir / "s.json") << text;
  return loadSceneJson((dir / "s.json").string());
}

TEST(SceneJson, AnimationKeysGiveTheExpectedTransforms) {
  Scene s = parseIn(testTempDir("scene-json-tf"), R"({
    "materials": [{"name": "m", "type": "diffuse"}],
    "meshes": [{"name": "b", "procedural": "box"}],
    "instances": [
      {"name": "looped", "mesh": "b", "material": "m", "scale": 2, "animation": {"loop": true,
       "keys": [{"time": 0}, {"time": 2, "translate": [2, 0, 4], "rotate": [0, 90, 0]}]}},
      {"name": "once", "mesh": "b", "material": "m", "translate": [0, 1, 0], "animation": {
       "keys": [{"time": 1, "translate": [0, 0, 0]}, {"time": 3, "translate": [4, 0, 0]}]}}]})");
  EXPECT_FLOAT_EQ(s.duration(), 3.0f);
  const Instance& looped = s.instances[0];
  auto at = [&](const Instance& inst, float t, vec3 p) {
    return transformPoint(inst.matrixAt(t), p);
  };
  // Halfway: translation halfway, 45 degrees about +Y, and the instance's scale 2 kept by both
  // keys.
  float c = 2.0f * std::cos(radians(45.0f));
  EXPECT_NEAR(glm::distance(at(looped, 1.0f, {1, 0, 0}), vec3(1 + c, 0, 2 - c)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(at(looped, 0.0f, {1, 0, 0}), vec3(2, 0, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(at(looped, 3.0f, {1, 0, 0}), at(looped, 1.0f, {1, 0, 0})), 0.0f, 1e-5f);
  const Instance& once = s.instances[1];
  EXPECT_NEAR(glm::distance(at(once, 0.0f, {0, 0, 0}), vec3(0, 0, 0)), 0.0f, 1e-6f);  // first holds
  EXPECT_NEAR(glm::distance(at(once, 2.0f, {0, 0, 0}), vec3(2, 0, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(at(once, 9.0f, {0, 0, 0}), vec3(4, 0, 0)), 0.0f, 1e-6f);  // last holds
}

TEST(SceneJson, MovingLightsRipplesAndGridQuadsAreRead) {
  Scene s = parseIn(testTempDir("scene-json-tf"), R"({
    "light": {"direction": [0, 1, 0], "color": [1, 1, 1], "loop": true,
              "keys": [{"time": 0}, {"time": 4, "direction": [1, 0, 0], "color": [0, 0, 1]}]},
    "materials": [{"name": "m", "type": "diffuse"}, {"name": "water", "type": "reflector"}],
    "meshes": [{"name": "pool", "procedural": "quad", "size": [2, 1], "cells": [20, 10]}],
    "instances": [
      {"name": "a", "mesh": "pool", "material": "water", "translate": [0, 1, 0],
       "deform": {"type": "ripple", "amplitude": 0.03, "wavelength": 0.4, "speed": 0.2,
                  "decay": 1.5, "center": [0.5, 0, 0]}},
      {"name": "b", "mesh": "pool", "material": "m"}]})");
  ASSERT_EQ(s.light.keys.size(), 2u);
  EXPECT_EQ(s.light.keys[0].direction, vec3(0, 1, 0));  // a key without fields is the light's own
  EXPECT_EQ(s.light.keys[0].color, vec3(1));
  EXPECT_NEAR(glm::dot(s.lightAt(2.0f).direction, glm::normalize(vec3(1, 1, 0))), 1.0f, 1e-5f);
  EXPECT_NEAR(s.lightAt(6.0f).direction.y, s.lightAt(2.0f).direction.y, 1e-5f);  // loops
  const Instance& a = s.instances[0];
  ASSERT_TRUE(a.deforms());
  EXPECT_EQ(a.deformation.kind, Deformation::Kind::kRipple);
  EXPECT_FLOAT_EQ(a.deformation.amplitude, 0.03f);
  EXPECT_FLOAT_EQ(a.deformation.wavelength, 0.4f);
  EXPECT_FLOAT_EQ(a.deformation.decay, 1.5f);
  EXPECT_EQ(a.deformation.center, vec3(0.5f, 0, 0));
  EXPECT_FLOAT_EQ(s.duration(), 4.0f);  // the light's 4 s outlast the ripple's 2 s period
  // The deforming instance got a copy of the mesh; the other keeps the original.
  EXPECT_NE(a.mesh, s.instances[1].mesh);
  EXPECT_EQ(s.meshes[size_t(a.mesh)].triangleCount(), 2u * 20u * 10u);
  EXPECT_EQ(s.meshes[size_t(a.mesh)].vertexCount(), 21u * 11u);
}

TEST(SceneJson, EulerAnglesApplyXThenYThenZ) {
  Scene s = parseIn(testTempDir("scene-json-tf"), R"({
    "materials": [{"name": "m", "type": "diffuse"}],
    "meshes": [{"name": "b", "procedural": "box"}],
    "instances": [{"mesh": "b", "material": "m", "rotate": [90, 90, 0]},
                  {"mesh": "b", "material": "m", "rotate": [0, 90, 90]}]})");
  // +Y: about X to +Z, then about Y to +X. (Y first would leave +Y at +Z.)
  vec3 v = s.instances[0].transform.rotation * vec3(0, 1, 0);
  EXPECT_NEAR(glm::distance(v, vec3(1, 0, 0)), 0.0f, 1e-6f);
  // +X: about Y to -Z, about Z unchanged.
  v = s.instances[1].transform.rotation * vec3(1, 0, 0);
  EXPECT_NEAR(glm::distance(v, vec3(0, 0, -1)), 0.0f, 1e-6f);
}

TEST(SceneJson, FitScalesUniformlyCentresAndGrounds) {
  Scene s = parseIn(testTempDir("scene-json-tf"), R"({
    "materials": [{"name": "m", "type": "diffuse"}],
    "meshes": [{"name": "grounded", "file": "box.ply", "fit": {"size": 2, "ground": true}},
               {"name": "centred", "file": "box.ply", "fit": {}},
               {"name": "raw", "file": "box.ply"}],
    "instances": [{"mesh": "grounded", "material": "m"}, {"mesh": "centred", "material": "m"},
                  {"mesh": "raw", "material": "m"}]})");
  auto near = [](vec3 a, vec3 b) { return glm::distance(a, b) < 1e-5f; };
  Bounds3 g = s.instanceBounds(0), c = s.instanceBounds(1), r = s.instanceBounds(2);
  EXPECT_TRUE(near(g.lo, {-1, 0, -0.25f}) && near(g.hi, {1, 1, 0.25f})) << g.lo.y << " " << g.hi.y;
  EXPECT_TRUE(near(c.lo, {-0.5f, -0.25f, -0.125f}) && near(c.hi, {0.5f, 0.25f, 0.125f}));
  EXPECT_TRUE(near(r.lo, {1, 2, 3}) && near(r.hi, {5, 4, 4}));
}

TEST(SceneJson, ModelInstancesBringTheFilesMeshes) {
  Scene s = parseIn(testTempDir("scene-json-tf"), R"({
    "materials": [{"name": "shiny", "type": "reflector"}],
    "meshes": [{"name": "block", "file": "box.ply", "fit": {"size": 1, "ground": true}}],
    "instances": [{"name": "plain", "model": "block", "translate": [0, 0, 3]},
                  {"name": "mirrored", "model": "block", "material_override": "shiny"}]})");
  ASSERT_EQ(s.instances.size(), 2u);  // a PLY holds one mesh
  const Instance& plain = s.instances[0];
  EXPECT_EQ(plain.name, "plain");
  EXPECT_EQ(s.materials[size_t(plain.material)].name, "model-default");
  EXPECT_FALSE(s.isReflector(0));
  EXPECT_TRUE(s.isReflector(1));
  EXPECT_EQ(s.instances[1].mesh, plain.mesh);  // loaded once
  Bounds3 b = s.instanceBounds(0);
  EXPECT_NEAR(b.extent().x, 1.0f, 1e-5f);
  EXPECT_NEAR(b.lo.y, 0.0f, 1e-5f);
  EXPECT_NEAR(b.center().z, 3.0f, 1e-5f);
}

}  // namespace
}  // namespace mirage::test
