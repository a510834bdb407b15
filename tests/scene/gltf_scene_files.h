// A whole glTF scene for the tests, built in memory: a mirror quad and a red box, two perspective
// cameras (cam_a, named by its camera, under a rotated and scaled parent; cam_b, named by its
// node), an orthographic camera, a KHR_lights_punctual directional light on a rotated node and a
// point light. Beside it, the values the node transforms give, worked out by hand.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/gltf_test_files.h"

namespace mirage::test {

// cam_a: parent "rig" T(0, 1, 0) Ry(kRigYaw) S(2), node "cam_a_node" T(0, 0.25, 2) Rx(-kPitch).
inline constexpr double kRigYaw = 30.0 * M_PI / 180.0;
inline constexpr double kPitch = 10.0 * M_PI / 180.0;
// cam_b: node "cam_b" T(-3, 1, 1) Ry(kYawB), no parent.
inline constexpr double kYawB = -70.0 * M_PI / 180.0;
// The sun: node "sun_node" rotated by Ry(kSunYaw) Rx(kSunPitch).
inline constexpr double kSunYaw = 45.0 * M_PI / 180.0;
inline constexpr double kSunPitch = -60.0 * M_PI / 180.0;

struct ExpectedCamera {
  vec3 position, forward, up;
  float fov_y_degrees, near_plane, far_plane, aspect;
};

// cam_a: position (0,1,0) + Ry(yaw) 2 (0, 0.25, 2); forward Ry(yaw) Rx(-pitch) (0,0,-1), up the
// same of (0,1,0); Ry(t) (x,y,z) = (x cos t + z sin t, y, -x sin t + z cos t).
inline ExpectedCamera expectedCamA() {
  const double s = std::sin(kRigYaw), c = std::cos(kRigYaw);
  const double sp = std::sin(kPitch), cp = std::cos(kPitch);
  return {vec3(4 * s, 1.5, 4 * c),
          vec3(-cp * s, -sp, -cp * c),
          vec3(-sp * s, cp, -sp * c),
          float(0.8 * 180.0 / M_PI),
          0.1f,
          50.0f,
          1.5f};
}

// cam_b: forward Ry(yaw) (0,0,-1) = (-sin yaw, 0, -cos yaw); no zfar: the 1000-unit far plane.
inline ExpectedCamera expectedCamB() {
  return {vec3(-3, 1, 1),
          vec3(-std::sin(kYawB), 0, -std::cos(kYawB)),
          vec3(0, 1, 0),
          float(0.6 * 180.0 / M_PI),
          0.05f,
          1000.0f,
          1.0f};
}

// Towards the sun: -Ry(yaw) Rx(pitch) (0,0,-1) = -Ry(yaw) (0, sin pitch, -cos pitch).
inline vec3 expectedSunDirection() {
  const double sp = std::sin(kSunPitch), cp = std::cos(kSunPitch);
  return vec3(cp * std::sin(kSunYaw), -sp, cp * std::cos(kSunYaw));
}
inline const vec3 kSunColor{2.0f, 1.8f, 1.6f};  // color (1, 0.9, 0.8) x intensity 2

// A unit quaternion [x, y, z, w] of `angle` about the unit `axis`.
inline nlohmann::json rotation(vec3 axis, double angle) {
  const double s = std::sin(angle / 2);
  return {axis.x * s, axis.y * s, axis.z * s, std::cos(angle / 2)};
}

// Ry(yaw) Rx(pitch) as a quaternion [x, y, z, w]: qy * qx.
inline nlohmann::json yawPitch(double yaw, double pitch) {
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  const double cx = std::cos(pitch / 2), sx = std::sin(pitch / 2);
  return {cy * sx, sy * cx, -sy * sx, cy * cx};
}

inline nlohmann::json cameraSceneNodes() {
  using nlohmann::json;
  return json::array({
      {{"name", "mirror"}, {"mesh", 0}, {"translation", {0, 2, -2}}, {"scale", {2, 2, 1}}},
      {{"name", "red_box"}, {"mesh", 1}, {"translation", {0, 0.5, 0}}},
      {{"name", "rig"},
       {"translation", {0, 1, 0}},
       {"rotation", rotation({0, 1, 0}, kRigYaw)},
       {"scale", {2, 2, 2}},
       {"children", {4}}},
      {{"name", "cam_b"},
       {"camera", 1},
       {"translation", {-3, 1, 1}},
       {"rotation", rotation({0, 1, 0}, kYawB)}},
      {{"name", "cam_a_node"},
       {"camera", 0},
       {"translation", {0, 0.25, 2}},
       {"rotation", rotation({1, 0, 0}, -kPitch)}},
      {{"name", "ortho_node"}, {"camera", 2}, {"translation", {0, 5, 0}}},
      {{"name", "sun_node"},
       {"rotation", yawPitch(kSunYaw, kSunPitch)},
       {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
      {{"name", "bulb_node"},
       {"translation", {0, 3, 0}},
       {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
  });
}

// The scene above: a 2 x 2 quad (z = 0) scaled to 4 x 4 at z = -2 standing on y = 0, and a unit
// box on y = 0 at the origin.
inline QuadScene cameraScene() {
  using nlohmann::json;
  QuadScene s;
  const size_t qp = s.buffer.add(std::vector<float>{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});
  const size_t qi = s.buffer.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3});
  std::vector<float> box;
  for (int v = 0; v < 8; ++v)
    box.insert(box.end(), {v & 1 ? 0.5f : -0.5f, v & 2 ? 0.5f : -0.5f, v & 4 ? 0.5f : -0.5f});
  const size_t bp = s.buffer.add(box);
  const size_t bi =
      s.buffer.add(std::vector<uint16_t>{0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                         2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5});
  auto view = [&](size_t offset, size_t bytes) {
    return json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
  };
  auto accessor = [](int v, int type, int count, const char* kind) {
    return json{{"bufferView", v}, {"componentType", type}, {"count", count}, {"type", kind}};
  };
  json qpos = accessor(0, 5126, 4, "VEC3"), bpos = accessor(2, 5126, 8, "VEC3");
  qpos["min"] = {-1, -1, 0}, qpos["max"] = {1, 1, 0};
  bpos["min"] = {-0.5, -0.5, -0.5}, bpos["max"] = {0.5, 0.5, 0.5};
  s.doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1, 2, 3, 5, 6, 7}}}}},
      {"nodes", cameraSceneNodes()},
      {"cameras",
       {{{"name", "cam_a"},
         {"type", "perspective"},
         {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 50}, {"aspectRatio", 1.5}}}},
        {{"type", "perspective"},
         {"perspective", {{"yfov", 0.6}, {"znear", 0.05}, {"aspectRatio", 1.0}}}},
        {{"name", "top"},
         {"type", "orthographic"},
         {"orthographic", {{"xmag", 2}, {"ymag", 2}, {"znear", 0.1}, {"zfar", 10}}}}}},
      {"extensions",
       {{"KHR_lights_punctual",
         {{"lights",
           {{{"name", "sun"},
             {"type", "directional"},
             {"color", {1.0, 0.9, 0.8}},
             {"intensity", 2.0}},
            {{"name", "bulb"}, {"type", "point"}, {"intensity", 5.0}}}}}}}},
      {"meshes",
       {{{"name", "quad"},
         {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}},
        {{"name", "box"},
         {"primitives", {{{"attributes", {{"POSITION", 2}}}, {"indices", 3}, {"material", 1}}}}}}},
      {"materials",
       {{{"name", "mirror"},
         {"pbrMetallicRoughness", {{"metallicFactor", 1}, {"roughnessFactor", 0}}}},
        {{"name", "red"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.8, 0.15, 0.1, 1}}, {"metallicFactor", 0}}}}}},
      {"accessors", {qpos, accessor(1, 5123, 6, "SCALAR"), bpos, accessor(3, 5123, 36, "SCALAR")}},
      {"bufferViews", {view(qp, 48), view(qi, 12), view(bp, 96), view(bi, 72)}},
  };
  return s;
}

}  // namespace mirage::test
