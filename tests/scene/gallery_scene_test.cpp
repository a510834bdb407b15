// The built-in scene `gallery` holds what per-reflector techniques need: two planar wall mirrors,
// a mirror sphere, a mirror teapot and a concave mirror, named so that an assignment can name
// them, among at least ten diffuse objects of different sizes; and every reflector shows in the
// main view and along the walk, as the ray tracer sees them.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/camera.h"
#include "raytrace/tracer.h"
#include "scene/builtin_scenes.h"
#include "scene/environment.h"

namespace mirage::test {
namespace {

const char* const kReflectors[] = {"mirror-back", "mirror-left", "mirror-sphere", "mirror-teapot",
                                   "concave-mirror"};

TEST(BuiltinGallery, HasEveryKindOfReflectorByName) {
  const Scene s = makeBuiltinScene("gallery");
  std::set<std::string> reflectors;
  for (int i : s.reflectorInstances()) reflectors.insert(s.instances[size_t(i)].name);
  EXPECT_EQ(reflectors, std::set<std::string>(std::begin(kReflectors), std::end(kReflectors)));
  std::set<std::string> planar;
  for (int i : s.reflectorInstances())
    if (isPlanarInstance(s, i, s.instances[size_t(i)].matrixAt(0.0f)))
      planar.insert(s.instances[size_t(i)].name);
  EXPECT_EQ(planar, (std::set<std::string>{"mirror-back", "mirror-left"}));
  // Diffuse objects besides the room, of sizes (bounding radii) a factor 5 or more apart.
  float smallest = 1e9f, largest = 0.0f;
  int diffuse = 0;
  for (int i = 0; i < int(s.instances.size()); ++i) {
    if (s.isReflector(i) || s.instances[size_t(i)].name == "room") continue;
    ++diffuse;
    const float r = s.instanceBounds(i, 0.0f).radius();
    smallest = std::min(smallest, r);
    largest = std::max(largest, r);
  }
  EXPECT_GE(diffuse, 10);
  EXPECT_GE(largest / smallest, 5.0f);
  EXPECT_NO_THROW(s.camera("main"));
  EXPECT_GE(s.camera("walk").path.keys.size(), 2u);
}

// The reflectors (1-based ids) that cover at least `min_pixels` pixels of the view.
std::set<uint32_t> reflectorsSeen(const RayTracer& tracer, const CameraDesc& camera, float t,
                                  size_t min_pixels) {
  TraceSettings settings;
  settings.order = 1;
  settings.progress = false;
  const TraceResult r = tracer.render(View(camera.at(t), {160, 112}), settings);
  std::map<uint32_t, size_t> count;
  for (uint32_t id : r.ids.pixels()) ++count[id];
  std::set<uint32_t> seen;
  for (const auto& [id, n] : count)
    if (id != 0 && n >= min_pixels) seen.insert(id);
  return seen;
}

TEST(BuiltinGallery, EveryReflectorShowsInTheMainViewAndOnTheWalk) {
  const Scene s = makeBuiltinScene("gallery");
  const EnvironmentMap env = EnvironmentMap::sky(s.light, 16);
  RayTracer tracer(s, env);
  tracer.prepare(0.0f);
  const size_t reflectors = s.reflectorInstances().size();
  EXPECT_EQ(reflectorsSeen(tracer, s.camera("main"), 0.0f, 40).size(), reflectors);
  const CameraDesc& walk = s.camera("walk");
  std::set<uint32_t> along;
  for (float t = 0.0f; t <= walk.path.keys.back().time; t += 1.0f)
    for (uint32_t id : reflectorsSeen(tracer, walk, t, 40)) along.insert(id);
  EXPECT_EQ(along.size(), reflectors);
}

}  // namespace
}  // namespace mirage::test
