// The built-in scene `plaza` is the scale case issue-sized scenes need: at least a million
// triangles, 200 objects and 16 reflectors, planar and curved; objects that do not cut into one
// another or the mirrors; and the reflectors in view, as the ray tracer sees them.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/camera.h"
#include "core/error.h"
#include "raytrace/tracer.h"
#include "scene/builtin_scenes.h"
#include "scene/environment.h"

namespace mirage::test {
namespace {

TEST(BuiltinPlaza, IsLargeWithPlanarAndCurvedReflectors) {
  const Scene s = makeBuiltinScene("plaza");
  EXPECT_GE(s.triangleCount(), size_t(1'000'000));
  EXPECT_GE(s.instances.size(), size_t(200));
  const std::vector<int> reflectors = s.reflectorInstances();
  EXPECT_GE(reflectors.size(), size_t(16));
  int planar = 0;
  for (int i : reflectors)
    if (isPlanarInstance(s, i, s.instances[size_t(i)].matrixAt(0.0f))) ++planar;
  EXPECT_GE(planar, 4);
  EXPECT_GE(int(reflectors.size()) - planar, 12);
}

// No two objects' bounds overlap but for the floor under them: every object stands on its own.
void expectObjectsApart(const Scene& s) {
  std::vector<Bounds3> bounds;
  std::vector<std::string> names;
  for (int i = 0; i < int(s.instances.size()); ++i)
    if (s.instances[size_t(i)].name != "floor") {
      bounds.push_back(s.instanceBounds(i, 0.0f));
      names.push_back(s.instances[size_t(i)].name);
    }
  int overlapping = 0;
  for (size_t a = 0; a < bounds.size(); ++a)
    for (size_t b = a + 1; b < bounds.size(); ++b) {
      const Bounds3& p = bounds[a];
      const Bounds3& q = bounds[b];
      const bool apart = glm::any(glm::lessThan(p.hi, q.lo)) || glm::any(glm::lessThan(q.hi, p.lo));
      if (!apart && ++overlapping <= 5)
        ADD_FAILURE() << names[a] << " and " << names[b] << " overlap";
    }
  EXPECT_EQ(overlapping, 0);
}

TEST(BuiltinPlaza, ObjectsStandApart) {
  expectObjectsApart(makeBuiltinScene("plaza"));
}

// The sweeps' scenes: --objects N lays out N objects, --reflectors N keeps N mirrors, all apart
// and every mirror over the floor.
TEST(BuiltinPlaza, ObjectsAndReflectorsFollowTheOptions) {
  for (const auto& [objects, reflectors] :
       {std::pair{10, 1}, std::pair{10, 32}, std::pair{100, 8}, std::pair{1000, 32}}) {
    SceneOptions options;
    options.objects = objects;
    options.reflectors = reflectors;
    const Scene s = makeBuiltinScene("plaza", options);
    EXPECT_EQ(int(s.diffuseInstances().size()), objects + 1);  // and the floor
    EXPECT_EQ(int(s.reflectorInstances().size()), reflectors);
    expectObjectsApart(s);
    const Bounds3 floor = s.instanceBounds(0);
    for (int r : s.reflectorInstances()) {
      const vec3 c = s.instanceBounds(r).center();
      EXPECT_TRUE(c.x >= floor.lo.x && c.x <= floor.hi.x && c.z >= floor.lo.z && c.z <= floor.hi.z)
          << s.instances[size_t(r)].name;
    }
  }
  const Scene defaults = makeBuiltinScene("plaza");
  EXPECT_EQ(defaults.diffuseInstances().size(), 241u);
  EXPECT_EQ(defaults.reflectorInstances().size(), 20u);
  for (const auto& [objects, reflectors] :
       {std::pair{9, -1}, std::pair{1001, -1}, std::pair{-1, 0}, std::pair{-1, 33}}) {
    SceneOptions options;
    options.objects = objects;
    options.reflectors = reflectors;
    EXPECT_THROW(makeBuiltinScene("plaza", options), InputError) << objects << " " << reflectors;
  }
  SceneOptions objects;
  objects.objects = 50;
  EXPECT_THROW(makeBuiltinScene("spheres9", objects), InputError);
}

TEST(BuiltinPlaza, MostReflectorsShowInTheMainView) {
  const Scene s = makeBuiltinScene("plaza");
  const EnvironmentMap env = EnvironmentMap::sky(s.light, 16);
  RayTracer tracer(s, env);
  tracer.prepare(0.0f);
  TraceSettings settings;
  settings.order = 1;
  settings.progress = false;
  const TraceResult r = tracer.render(View(s.camera("main").at(0.0f), {360, 256}), settings);
  std::map<uint32_t, size_t> count;
  for (uint32_t id : r.ids.pixels()) ++count[id];
  std::set<uint32_t> seen;
  for (const auto& [id, n] : count)
    if (id != 0 && n >= 20) seen.insert(id);
  EXPECT_GE(seen.size(), size_t(16)) << "of " << s.reflectorInstances().size();
}

}  // namespace
}  // namespace mirage::test
