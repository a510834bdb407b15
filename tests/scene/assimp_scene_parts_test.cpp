// Cameras and lights of files read through assimp: a COLLADA file the test writes, placed like
// the glTF test scene's (gltf_scene_files.h), and that glTF scene itself read through assimp.
#include <gtest/gtest.h>

#include "scene/gltf_scene_files.h"
#include "scene/log_capture.h"
#include "scene/model_loader.h"
#include "scene/model_loader_files.h"

namespace mirage {
namespace {

using test::expectInputError;
using test::LogCapture;
using test::TempDir;

constexpr float kTolerance = 1e-5f;
// COLLADA gives angles in degrees; assimp turns yfov and the aspect into a horizontal angle.
constexpr float kFovTolerance = 1e-4f;

void expectNear(vec3 got, vec3 want, const char* what) {
  EXPECT_NEAR(glm::distance(got, want), 0.0f, kTolerance)
      << what << ": (" << got.x << ", " << got.y << ", " << got.z << ") want (" << want.x << ", "
      << want.y << ", " << want.z << ")";
}

void expectPlaced(const CameraDesc& c, const test::ExpectedCamera& want) {
  SCOPED_TRACE(c.name);
  expectNear(c.position, want.position, "position");
  expectNear(glm::normalize(c.target - c.position), want.forward, "forward");
  expectNear(c.up, want.up, "up");
}

// cam_a's and the sun's nodes of the glTF test scene in COLLADA (angles in degrees; rotations
// apply in the order written, as glTF's T R S), a camera given by xfov alone, and a point light.
std::string colladaScene(const std::string& cam_a_optics) {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_cameras>
    <camera id="cam_a" name="cam_a"><optics><technique_common><perspective>)" +
         cam_a_optics + R"(</perspective></technique_common></optics></camera>
    <camera id="wide" name="wide"><optics><technique_common><perspective>
      <xfov>60</xfov><znear>0.5</znear><zfar>20</zfar>
    </perspective></technique_common></optics></camera>
  </library_cameras>
  <library_lights>
    <light id="sun" name="sun"><technique_common><directional><color>1 0.5 0.25</color>
    </directional></technique_common></light>
    <light id="bulb" name="bulb"><technique_common><point><color>1 1 1</color>
    </point></technique_common></light>
  </library_lights>
  <library_geometries>
    <geometry id="tri" name="tri"><mesh>
      <source id="pos"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#pa" count="3" stride="3"><param name="X"
          type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
      <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p>
      </triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="s">
    <node id="rig" name="rig"><translate>0 1 0</translate><rotate>0 1 0 30</rotate>
      <scale>2 2 2</scale>
      <node id="cam_a_node" name="cam_a_node"><translate>0 0.25 2</translate>
        <rotate>1 0 0 -10</rotate><instance_camera url="#cam_a"/></node>
    </node>
    <node id="wide_node" name="wide_node"><translate>0 3 5</translate>
      <instance_camera url="#wide"/></node>
    <node id="sun_node" name="sun_node"><rotate>0 1 0 45</rotate><rotate>1 0 0 -60</rotate>
      <instance_light url="#sun"/></node>
    <node id="bulb_node" name="bulb_node"><instance_light url="#bulb"/></node>
    <node id="tri_node" name="tri_node"><instance_geometry url="#tri"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
}

TEST(AssimpSceneParts, ColladaCamerasAndLightFollowTheNodeTransforms) {
  TempDir dir;
  // yfov 0.8 rad (cam_a of the glTF scene) in degrees, with the aspect: assimp makes a
  // horizontal angle of them, which the reader turns back into the vertical one.
  const std::string path =
      dir.write("scene.dae", colladaScene("<yfov>45.836624</yfov><aspect_ratio>1.5</aspect_ratio>"
                                          "<znear>0.1</znear><zfar>50</zfar>"));
  LogCapture log;
  const LoadedModel m = loadModel(path);
  ASSERT_EQ(m.cameras.size(), 2u);
  const CameraDesc& a = m.cameras[0];
  EXPECT_EQ(a.name, "cam_a_node");  // assimp names cameras after their nodes
  expectPlaced(a, test::expectedCamA());
  EXPECT_NEAR(a.fov_y_degrees, 45.836624f, kFovTolerance);
  EXPECT_NEAR(a.aspect, 1.5f, kTolerance);
  EXPECT_NEAR(a.near_plane, 0.1f, kTolerance);
  EXPECT_NEAR(a.far_plane, 50.0f, kTolerance);

  // xfov alone: no aspect, so the horizontal angle is taken as the vertical one, with a warning.
  const CameraDesc& w = m.cameras[1];
  expectPlaced(w, {vec3(0, 3, 5), vec3(0, 0, -1), vec3(0, 1, 0), 0, 0, 0, 0});
  EXPECT_NEAR(w.fov_y_degrees, 60.0f, kFovTolerance);
  EXPECT_EQ(w.aspect, 0.0f);
  EXPECT_EQ(log.count({"warning", path, "'wide_node'", "no aspect ratio"}), 1u);

  ASSERT_TRUE(m.light.has_value());
  expectNear(m.light->direction, test::expectedSunDirection(), "light direction");
  expectNear(m.light->color, vec3(1, 0.5, 0.25), "light colour");
  EXPECT_EQ(log.count({"warning", path, "'bulb_node'", "point light", "ignored"}), 1u);
  EXPECT_EQ(m.mesh_node, std::vector<std::string>{"tri_node"});
}

TEST(AssimpSceneParts, BadCameraNumbersNameTheFileCameraAndField) {
  TempDir dir;
  // (assimp's own validation refuses a far plane before the near one.)
  const std::string path =
      dir.write("bad.dae", colladaScene("<xfov>200</xfov><znear>0.1</znear><zfar>10</zfar>"));
  expectInputError([&] { loadModel(path); },
                   {path, "camera 'cam_a_node'", "mHorizontalFOV", "allowed range (0, 3.14159)"});
}

// glTF through assimp (what files needing Draco take): assimp 5.2 copies a camera node's
// translation into the camera's position and stores yfov x aspect as the horizontal angle; the
// cameras come out where tinygltf's reading puts them.
TEST(AssimpSceneParts, GltfThroughAssimpMatchesTheOwnReader) {
  TempDir dir;
  test::QuadScene s = test::cameraScene();
  const std::string path = test::writeGltf(dir, s, "scene.gltf");
  const LoadedModel own = loadGltf(path), through = loadWithAssimp(path);
  ASSERT_EQ(through.cameras.size(), own.cameras.size());
  EXPECT_EQ(through.cameras[0].name, "cam_a_node");  // assimp knows the node's name only
  EXPECT_EQ(through.cameras[1].name, "cam_b");
  for (size_t i = 0; i < own.cameras.size(); ++i) {
    const CameraDesc &a = own.cameras[i], &b = through.cameras[i];
    SCOPED_TRACE(a.name);
    expectNear(b.position, a.position, "position");
    expectNear(b.target, a.target, "target");
    expectNear(b.up, a.up, "up");
    EXPECT_NEAR(b.fov_y_degrees, a.fov_y_degrees, kFovTolerance);
    EXPECT_NEAR(b.near_plane, a.near_plane, kTolerance);
    EXPECT_NEAR(b.aspect, a.aspect, kTolerance);
  }
  ASSERT_TRUE(through.light.has_value());
  expectNear(through.light->direction, own.light->direction, "light direction");
  expectNear(through.light->color, own.light->color, "light colour");
}

}  // namespace
}  // namespace mirage
