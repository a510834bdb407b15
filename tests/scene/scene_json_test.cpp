// JSON scene files: a full scene parses into the expected Scene; every kind of bad input is an
// InputError naming the file and the JSON path of the field; animation, Euler angles and `fit`
// give the documented transforms.
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "scene/scene_json.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Restores MIRAGE_ASSET_DIR when a test that points it elsewhere ends.
class AssetDirGuard {
 public:
  explicit AssetDirGuard(const fs::path& dir) {
    if (const char* old = std::getenv("MIRAGE_ASSET_DIR")) old_ = old;
    setenv("MIRAGE_ASSET_DIR", dir.c_str(), 1);
  }
  ~AssetDirGuard() {
    if (old_)
      setenv("MIRAGE_ASSET_DIR", old_->c_str(), 1);
    else
      unsetenv("MIRAGE_ASSET_DIR");
  }

 private:
  std::optional<std::string> old_;
};

// A valid scene using every section; the error cases below break one field of it.
json fullScene() {
  return json::parse(R"({
    "name": "full", "description": "every section",
    "environment": {"image": "sky.exr", "intensity": 2, "rotation": 30, "clamp": 50, "cube_size": 64},
    "light": {"direction": [0, 2, 0], "color": [1, 0.5, 0.25], "ambient": [0.1, 0.2, 0.3]},
    "textures": [{"name": "wood", "file": "tex/wood.png"}, {"name": "bumps", "file": "tex/bumps.png"}],
    "materials": [
      {"name": "checker", "type": "diffuse", "albedo": [0.9, 0.9, 0.9],
       "checker": {"color": [0.1, 0.2, 0.3], "scale": 2}},
      {"name": "mirror", "type": "reflector", "base": [0.1, 0.1, 0.1], "tint": [0.9, 0.8, 0.7],
       "reflectivity": 0.5, "fresnel_f0": 0.04, "attenuation_range": 3, "normal_map": "bumps"},
      {"name": "wood", "type": "diffuse", "texture": "wood"},
      {"name": "plain", "type": "diffuse"}
    ],
    "meshes": [
      {"name": "box", "file": "box.ply", "fit": {"size": 2, "ground": true}},
      {"name": "floor", "procedural": "quad", "size": [16, 8], "uv_per_unit": 2},
      {"name": "ball", "procedural": "sphere", "radius": 0.5, "segments": 16, "rings": 8},
      {"name": "unused", "procedural": "torus"}
    ],
    "instances": [
      {"name": "floor", "mesh": "floor", "material": "checker"},
      {"name": "ball", "mesh": "ball", "material": "mirror", "translate": [1, 2, 3],
       "rotate": [0, 90, 0], "scale": [1, 2, 3]},
      {"mesh": "box", "material": "plain", "scale": 0.5},
      {"name": "wooden", "mesh": "ball", "material": "wood"}
    ],
    "cameras": [
      {"name": "main", "position": [0, 2, 6], "target": [0, 1, 0], "fov_y": 50, "near": 0.1, "far": 100},
      {"position": [5, 5, 5], "target": [0, 0, 0]},
      {"name": "walk", "fov_y": 40, "path": [
        {"time": 0, "position": [4, 1.7, 4], "target": [0, 1, 0]},
        {"time": 2, "position": [0, 1.6, 5], "target": [0, 1, 0]},
        {"time": 5, "position": [-4, 1.7, 4], "target": [0, 1.2, 0]}]}
    ]
  })");
}

// Writes the files fullScene() refers to, and the scene (after `edit`) as bad.json.
fs::path writeScene(const fs::path& dir, const json& scene,
                    const std::string& name = "scene.json") {
  writeExr((dir / "sky.exr").string(), Image(8, 4, vec4(0.5f, 0.6f, 0.7f, 1.0f)));
  fs::create_directories(dir / "tex");
  writePng((dir / "tex/wood.png").string(), Image(2, 2, vec4(0.5f, 0.25f, 0.1f, 1.0f)));
  writePng((dir / "tex/bumps.png").string(), Image(2, 2, vec4(0.5f, 0.5f, 1.0f, 1.0f)));
  writeText(dir / "box.ply", boxPlyText({1, 2, 3}, {5, 4, 4}));
  writeText(dir / name, scene.dump(2));
  return dir / name;
}

TEST(SceneJson, FullSceneParsesIntoTheExpectedScene) {
  fs::path dir = testTempDir("scene-json");
  fs::path file = writeScene(dir, fullScene());
  Scene s = loadSceneJson(file.string());
  EXPECT_EQ(s.name, "full");
  EXPECT_EQ(s.description, "every section");
  EXPECT_EQ(s.source, file.string());

  EXPECT_TRUE(fs::equivalent(s.environment.image, dir / "sky.exr"));
  EXPECT_FLOAT_EQ(s.environment.intensity, 2.0f);
  EXPECT_FLOAT_EQ(s.environment.rotation_degrees, 30.0f);
  EXPECT_FLOAT_EQ(s.environment.clamp, 50.0f);
  EXPECT_EQ(s.environment.cube_size, 64);
  EXPECT_EQ(s.light.direction, vec3(0, 1, 0));  // normalised
  EXPECT_EQ(s.light.color, vec3(1, 0.5f, 0.25f));
  EXPECT_EQ(s.light.ambient, vec3(0.1f, 0.2f, 0.3f));

  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.textures[0].name, "wood");
  EXPECT_TRUE(s.textures[0].srgb);
  EXPECT_FALSE(s.textures[1].srgb);  // used as a normal map: linear data
  EXPECT_EQ(s.textures[1].image.width(), 2);
  EXPECT_NEAR(s.textures[1].image(0, 0).x, 128.0f / 255.0f, 1e-3f);  // not sRGB-decoded

  ASSERT_EQ(s.materials.size(), 4u);
  const Material& checker = s.materials[0];
  EXPECT_FALSE(checker.isReflector());
  EXPECT_EQ(checker.albedo, vec3(0.9f));
  EXPECT_EQ(checker.checker_color, vec3(0.1f, 0.2f, 0.3f));
  EXPECT_FLOAT_EQ(checker.checker_scale, 2.0f);
  const Material& mirror = s.materials[1];
  EXPECT_TRUE(mirror.isReflector());
  EXPECT_EQ(mirror.albedo, vec3(0.1f));
  EXPECT_EQ(mirror.tint, vec3(0.9f, 0.8f, 0.7f));
  EXPECT_FLOAT_EQ(mirror.reflectivity, 0.5f);
  EXPECT_FLOAT_EQ(mirror.fresnel_f0, 0.04f);
  EXPECT_FLOAT_EQ(mirror.attenuation_range, 3.0f);
  EXPECT_EQ(mirror.normal_map, 1);
  EXPECT_EQ(s.materials[2].albedo_texture, 0);

  // Only used meshes are built: floor, ball, box (the unused torus is not).
  ASSERT_EQ(s.meshes.size(), 3u);
  ASSERT_EQ(s.instances.size(), 4u);
  const Instance& floor = s.instances[0];
  EXPECT_EQ(s.meshes[size_t(floor.mesh)].name, "floor");
  Bounds3 fb = s.meshes[size_t(floor.mesh)].bounds();
  EXPECT_FLOAT_EQ(fb.extent().x, 16.0f);
  EXPECT_FLOAT_EQ(fb.extent().z, 8.0f);
  const Instance& ball = s.instances[1];
  EXPECT_EQ(ball.material, 1);
  EXPECT_EQ(ball.transform.translation, vec3(1, 2, 3));
  EXPECT_EQ(ball.transform.scale, vec3(1, 2, 3));
  vec3 x = ball.transform.rotation * vec3(1, 0, 0);
  EXPECT_NEAR(glm::distance(x, vec3(0, 0, -1)), 0.0f, 1e-6f);  // 90 degrees about +Y
  EXPECT_FALSE(s.meshes[size_t(ball.mesh)].tangents.empty());  // for the normal map
  EXPECT_EQ(s.instances[2].name, "box-3");                     // a default name
  EXPECT_EQ(s.instances[2].transform.scale, vec3(0.5f));
  EXPECT_EQ(s.instances[3].mesh, ball.mesh);  // one mesh, two instances

  ASSERT_EQ(s.cameras.size(), 3u);
  EXPECT_EQ(s.cameras[0].name, "main");
  EXPECT_TRUE(s.cameras[0].path.empty());
  EXPECT_EQ(s.cameras[0].position, vec3(0, 2, 6));
  EXPECT_FLOAT_EQ(s.cameras[0].fov_y_degrees, 50.0f);
  EXPECT_FLOAT_EQ(s.cameras[0].near_plane, 0.1f);
  EXPECT_FLOAT_EQ(s.cameras[0].far_plane, 100.0f);
  EXPECT_EQ(s.cameras[1].name, "camera-2");
  // A camera with a path: its keys as given, its first key as its still placement.
  const CameraDesc& walk = s.cameras[2];
  ASSERT_EQ(walk.path.keys.size(), 3u);
  EXPECT_FLOAT_EQ(walk.fov_y_degrees, 40.0f);
  EXPECT_FLOAT_EQ(walk.path.keys[2].time, 5.0f);
  EXPECT_EQ(walk.path.keys[1].position, vec3(0, 1.6f, 5));
  EXPECT_EQ(walk.path.keys[2].target, vec3(0, 1.2f, 0));
  EXPECT_EQ(walk.position, vec3(4, 1.7f, 4));
  EXPECT_EQ(walk.target, vec3(0, 1, 0));
  EXPECT_EQ(walk.at(2.0f).position, vec3(0, 1.6f, 5));
}

TEST(SceneJson, MinimalSceneGetsDefaultsAndACamera) {
  fs::path dir = testTempDir("scene-json");
  writeText(dir / "tiny.json", R"({"materials": [{"name": "m", "type": "diffuse"}],
    "meshes": [{"name": "b", "procedural": "box"}],
    "instances": [{"mesh": "b", "material": "m"}]})");
  Scene s = loadSceneJson((dir / "tiny.json").string());
  EXPECT_EQ(s.name, "tiny");
  EXPECT_TRUE(s.environment.image.empty());  // the procedural sky
  EXPECT_EQ(s.light.direction, Light{}.direction);
  ASSERT_EQ(s.cameras.size(), 1u);  // ensureCamera()
  EXPECT_EQ(s.materials[0].albedo, vec3(0.8f));
}

struct BadCase {
  std::string label;
  std::function<void(json&)> edit;
  std::vector<std::string> expected;  // pieces of the message besides the file name
};

void PrintTo(const BadCase& c, std::ostream* os) {
  *os << c.label;
}

class SceneJsonBad : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneJsonBad, IsAnInputErrorNamingFileAndField) {
  fs::path dir = testTempDir("scene-json");
  AssetDirGuard assets(dir / "assets");
  json scene = fullScene();
  GetParam().edit(scene);
  fs::path file = writeScene(dir, scene, "bad.json");
  try {
    loadSceneJson(file.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    for (const std::string& piece : GetParam().expected)
      EXPECT_NE(msg.find(piece), std::string::npos) << "'" << piece << "' not in: " << msg;
    EXPECT_LT(msg.size(), 700u) << msg;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneJsonBad,
    ::testing::Values(
        BadCase{"unknown key",
                [](json& s) { s["materials"][1]["fresnel"] = 0.5; },
                {"materials[1].fresnel: unknown field", "reflector material", "fresnel_f0"}},
        BadCase{"unknown top-level key",
                [](json& s) { s["camera"] = json::array(); },
                {"camera: unknown field", "cameras"}},
        BadCase{"key of the other material type",
                [](json& s) {
                  s["materials"][0]["tint"] = {1, 1, 1};
                },
                {"materials[0].tint: unknown field", "diffuse material"}},
        BadCase{"wrong type",
                [](json& s) { s["materials"][0]["albedo"] = "red"; },
                {"materials[0].albedo = 'red'", "array of 3 numbers"}},
        BadCase{"wrong arity",
                [](json& s) {
                  s["light"]["color"] = {1, 1};
                },
                {"light.color", "array of 3 numbers"}},
        BadCase{"number as string",
                [](json& s) { s["meshes"][2]["radius"] = "1"; },
                {"meshes[2].radius", "expected a number", "(0, 1000000]"}},
        BadCase{"out of range",
                [](json& s) { s["materials"][1]["fresnel_f0"] = 1.5; },
                {"materials[1].fresnel_f0 = 1.5 is outside the allowed range [0, 1]"}},
        BadCase{"vector component out of range",
                [](json& s) { s["materials"][1]["tint"][2] = -1; },
                {"materials[1].tint[2] = -1", "[0, 1]"}},
        BadCase{"not an integer",
                [](json& s) { s["meshes"][2]["segments"] = 3.5; },
                {"meshes[2].segments = 3.5", "integer", "3..2048"}},
        BadCase{"too few segments",
                [](json& s) { s["meshes"][2]["segments"] = 2; },
                {"meshes[2].segments = 2 is outside", "3..2048"}},
        BadCase{"unknown generator",
                [](json& s) { s["meshes"][2]["procedural"] = "cube"; },
                {"meshes[2].procedural = 'cube'", "sphere, box, quad"}},
        BadCase{"empty lathe",
                [](json& s) {
                  s["meshes"][3] = {{"name", "unused"}, {"procedural", "lathe"},
                                    {"profile", {{0, 0}, {0, 1}}}};
                },
                {"meshes[3].profile has only radius-0 points"}},
        BadCase{"far away", [](json& s) { s["instances"][0]["translate"] = {0, 1e9, 0}; },
                {"instances[0].translate[1] = 1000000000 is outside", "[-1000000, 1000000]"}},
        BadCase{"file and procedural",
                [](json& s) { s["meshes"][1]["file"] = "box.ply"; },
                {"meshes[1]", "exactly one of file"}},
        BadCase{
            "unknown material",
            [](json& s) { s["instances"][1]["material"] = "mirorr"; },
            {"instances[1].material = 'mirorr': no such material", "checker, mirror, plain, wood"}},
        BadCase{"unknown mesh",
                [](json& s) { s["instances"][0]["mesh"] = "flor"; },
                {"instances[0].mesh = 'flor': no such mesh", "ball, box, floor"}},
        BadCase{"unknown texture",
                [](json& s) { s["materials"][2]["texture"] = "oak"; },
                {"materials[2].texture = 'oak': no such texture", "bumps, wood"}},
        BadCase{"missing required field",
                [](json& s) { s["instances"][1].erase("mesh"); },
                {"instances[1].mesh is required"}},
        BadCase{
            "missing instances", [](json& s) { s.erase("instances"); }, {"instances is required"}},
        BadCase{"missing file",
                [](json& s) { s["meshes"][0]["file"] = "nope.ply"; },
                {"meshes[0].file = 'nope.ply': no such file"}},
        BadCase{"missing texture file",
                [](json& s) { s["textures"][0]["file"] = "tex/oak.png"; },
                {"textures[0].file = 'tex/oak.png': no such file"}},
        BadCase{"assets: path escaping",
                [](json& s) { s["meshes"][0]["file"] = "assets:../box.ply"; },
                {"meshes[0].file = 'assets:../box.ply'", "inside the asset directory"}},
        BadCase{"absolute assets: path",
                [](json& s) { s["environment"]["image"] = "assets:/etc/x.exr"; },
                {"environment.image", "inside the asset directory"}},
        BadCase{"missing asset",
                [](json& s) { s["meshes"][0]["file"] = "assets:teapot/teapot.ply"; },
                {"meshes[0].file = 'assets:teapot/teapot.ply'", "scripts/fetch-assets"}},
        BadCase{"environment not an image",
                [](json& s) { s["environment"]["image"] = "box.ply"; },
                {"environment.image = 'box.ply': not an image file"}},
        BadCase{"not a mesh file",
                [](json& s) { s["meshes"][0]["file"] = "sky.exr"; },
                {"meshes[0].file = 'sky.exr': not a mesh file"}},
        BadCase{"duplicate name",
                [](json& s) { s["materials"][2]["name"] = "checker"; },
                {"materials[2].name = 'checker' is already"}},
        BadCase{"duplicate instance name",
                [](json& s) { s["instances"][3]["name"] = "floor"; },
                {"instances[3].name = 'floor' is already"}},
        BadCase{"default name taken",
                [](json& s) { s["instances"][0]["name"] = "box-3"; },
                {"instances[2] gets the default name 'box-3'"}},
        BadCase{"duplicate mesh name",
                [](json& s) { s["meshes"][3]["name"] = "box"; },
                {"meshes[3].name = 'box' is already"}},
        BadCase{"keys out of order",
                [](json& s) {
                  s["instances"][1]["animation"] = json::parse(
                      R"({"keys": [{"time": 2}, {"time": 1, "translate": [0, 0, 0]}]})");
                },
                {"instances[1].animation.keys[1].time = 1 must be greater", "(2)"}},
        BadCase{"no keys",
                [](json& s) {
                  s["instances"][1]["animation"] = {{"keys", json::array()}};
                },
                {"instances[1].animation.keys is empty"}},
        BadCase{"negative scale",
                [](json& s) { s["instances"][1]["scale"] = -1; },
                {"instances[1].scale = -1 is outside the allowed range (0, 1000000]"}},
        BadCase{"fov",
                [](json& s) { s["cameras"][0]["fov_y"] = 200; },
                {"cameras[0].fov_y = 200 is outside the allowed range (0, 180)"}},
        BadCase{"far before near",
                [](json& s) { s["cameras"][0]["far"] = 0.01; },
                {"cameras[0].far = 0.01", "> 0.1"}},
        BadCase{"camera without direction",
                [](json& s) {
                  s["cameras"][1]["target"] = {5, 5, 5};
                },
                {"cameras[1].target equals the position"}},
        BadCase{"path with one key",
                [](json& s) {
                  s["cameras"][2]["path"].erase(2);
                  s["cameras"][2]["path"].erase(1);
                },
                {"cameras[2].path has 1 key", "at least 2"}},
        BadCase{"path not an array",
                [](json& s) { s["cameras"][2]["path"] = 3; },
                {"cameras[2].path must be an array"}},
        BadCase{"path times not increasing",
                [](json& s) { s["cameras"][2]["path"][2]["time"] = 2; },
                {"cameras[2].path[2].time = 2 must be greater", "(2)"}},
        BadCase{"negative path time",
                [](json& s) { s["cameras"][2]["path"][0]["time"] = -1; },
                {"cameras[2].path[0].time = -1 is outside", "[0, 1000000]"}},
        BadCase{"path key without position",
                [](json& s) { s["cameras"][2]["path"][1].erase("position"); },
                {"cameras[2].path[1].position is required"}},
        BadCase{"path key looking at its eye",
                [](json& s) {
                  s["cameras"][2]["path"][1]["target"] = {0, 1.6, 5};
                },
                {"cameras[2].path[1].target equals the position"}},
        BadCase{"path key looking straight up",
                [](json& s) {
                  s["cameras"][2]["path"][0]["target"] = {4, 9, 4};
                },
                {"cameras[2].path[0].target", "parallel to the camera's up"}},
        BadCase{"path passing through its target",
                [](json& s) {
                  s["cameras"][2]["path"] = json::parse(R"([
                    {"time": 0, "position": [0, 1, 2], "target": [0, 1, 0]},
                    {"time": 1, "position": [0, 1, -2], "target": [0, 1, 0]}])");
                },
                {"cameras[2].path at time 0.5", "target on the eye"}},
        BadCase{"unknown path key field",
                [](json& s) { s["cameras"][2]["path"][0]["fov_y"] = 30; },
                {"cameras[2].path[0].fov_y: unknown field", "camera path key"}},
        BadCase{"path and position",
                [](json& s) {
                  s["cameras"][2]["position"] = {1, 1, 1};
                },
                {"cameras[2].position cannot be combined with path"}},
        BadCase{"zero light",
                [](json& s) {
                  s["light"]["direction"] = {0, 0, 0};
                },
                {"light.direction", "must not be zero"}},
        BadCase{"light keys out of order",
                [](json& s) {
                  s["light"]["keys"] = json::parse(R"([{"time": 2}, {"time": 1}])");
                },
                {"light.keys[1].time = 1 must be greater", "(2)"}},
        BadCase{"light key opposite",
                [](json& s) {
                  s["light"]["keys"] = json::parse(
                      R"([{"time": 0, "direction": [0, 1, 0]},
                          {"time": 1, "direction": [0, -1, 0]}])");
                },
                {"light.keys[1].direction is opposite", "add a key in between"}},
        BadCase{"unknown deformation",
                [](json& s) {
                  s["instances"][1]["deform"] = {{"type", "wobble"}};
                },
                {"instances[1].deform.type = 'wobble'", "allowed: ripple"}},
        BadCase{"ripple wavelength",
                [](json& s) {
                  s["instances"][1]["deform"] = {{"type", "ripple"}, {"wavelength", 0}};
                },
                {"instances[1].deform.wavelength = 0", "(0, 1000000]"}},
        BadCase{"diffuse deforms",
                [](json& s) {
                  s["instances"][0]["deform"] = {{"type", "ripple"}};
                },
                {"instances[0].deform applies to reflectors only"}},
        BadCase{"quad cells",
                [](json& s) { s["meshes"][1]["cells"] = {2.5, 3}; },
                {"meshes[1].cells", "whole numbers in 1..1024"}},
        BadCase{"cube size",
                [](json& s) { s["environment"]["cube_size"] = 4; },
                {"environment.cube_size = 4", "8..4096"}},
        BadCase{"material type",
                [](json& s) { s["materials"][0]["type"] = "metal"; },
                {"materials[0].type = 'metal'", "diffuse, reflector"}},
        BadCase{"texture and checker",
                [](json& s) { s["materials"][0]["texture"] = "wood"; },
                {"materials[0].texture cannot be combined with checker"}},
        BadCase{"model and mesh",
                [](json& s) {
                  s["instances"][2]["model"] = "box";
                  s["instances"][2].erase("material");
                },
                {"instances[2].mesh cannot be combined with model"}},
        BadCase{"procedural model",
                [](json& s) {
                  s["instances"][0] = {{"model", "ball"}};
                },
                {"instances[0].model", "procedural"}},
        BadCase{"texture on a mesh without uvs",
                [](json& s) { s["instances"][2]["material"] = "wood"; },
                {"instances[2]", "texture coordinates"}},
        BadCase{"section of the wrong type",
                [](json& s) { s["materials"] = {{"name", "x"}}; },
                {"materials must be an array"}},
        BadCase{"instance not an object",
                [](json& s) { s["instances"][0] = 7; },
                {"instances[0] must be an instance"}},
        BadCase{"huge unknown key",
                [](json& s) { s[std::string(100000, 'k')] = 1; },
                {"kkkk...: unknown field"}}));

// Input that is not a scene object at all.
void expectFileError(const std::string& text, const std::string& piece) {
  fs::path dir = testTempDir("scene-json");
  writeText(dir / "raw.json", text);
  try {
    loadSceneJson((dir / "raw.json").string());
    FAIL() << "no error for " << text.substr(0, 40);
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find((dir / "raw.json").string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(piece), std::string::npos) << msg;
    EXPECT_LT(msg.size(), 700u) << msg;
  }
}

TEST(SceneJson, EmptyFile) {
  expectFileError("", "the file is empty");
  expectFileError(" \n\t ", "the file is empty");
}

TEST(SceneJson, NotJson) {
  expectFileError("this is not json", "not valid JSON");
  expectFileError("{\"name\": \"x\",}", "line 1");
  expectFileError("\x89PNG\r\n\x1a\n\x01\x02", "not valid JSON");
  expectFileError("{\"name\": \"" + std::string(100000, 'x'), "not valid JSON");
  expectFileError("{\"name\": 1e999}", "not valid JSON");
}

TEST(SceneJson, TopLevelMustBeAnObject) {
  expectFileError("[1, 2]", "JSON object");
  expectFileError("42", "JSON object");
}

TEST(SceneJson, DeepNestingIsRejectedWhileParsing) {
  // 100,000 levels would overflow the stack of any recursive walk or dump().
  std::string deep =
      "{\"description\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  expectFileError(deep, "deeper than 64");
  std::string objects;
  for (int i = 0; i < 70; ++i) objects += "{\"a\": ";
  objects += "1" + std::string(70, '}');
  expectFileError(objects, "deeper than 64");
}

TEST(SceneJson, MissingSceneFile) {
  fs::path dir = testTempDir("scene-json");
  EXPECT_THROW(loadSceneJson((dir / "none.json").string()), InputError);
  EXPECT_THROW(loadSceneJson(dir.string()), InputError);
}

}  // namespace
}  // namespace mirage::test
