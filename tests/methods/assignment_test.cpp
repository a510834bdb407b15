// Reflection assignments (methods/assignment.h): the `--assign` text and a scene file's
// "reflections" resolve to one method per reflector, and every mistake is an InputError that
// names the entry and what exists.
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "methods/assignment.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"

namespace mirage {
namespace {

// The message of the InputError `fn` throws ("" and a failure when it throws none).
std::string inputError(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

std::vector<std::string> namesOf(const Scene& scene, const AssignedPart& part) {
  std::vector<std::string> out;
  for (int i : part.reflectors) out.push_back(scene.instances[size_t(i)].name);
  return out;
}

TEST(Assignment, TextParsesEntriesGlobsAndParameters) {
  const auto rules = parseAssignText(
      "mirror-back,mirror-left=planar;mirror-s*=depthmap:srdm-m=16,"
      "order=3;;*=envmap-box:envmap-size=64;");
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[0].reflectors, (std::vector<std::string>{"mirror-back", "mirror-left"}));
  EXPECT_EQ(rules[1].method, "depthmap");
  EXPECT_EQ(rules[1].params.at("srdm-m"), "16");
  EXPECT_EQ(rules[1].params.at("order"), "3");
  EXPECT_EQ(rules[2].where, "--assign entry 3");
  // And back: the text is what the parser reads again.
  EXPECT_EQ(parseAssignText(assignText(rules))[1].params, rules[1].params);
  for (const char* bad :
       {"", ";", "planar", "=planar", "a=", "a=planar:order", "a=planar:=2", ",a=planar"})
    EXPECT_NE(inputError([&] { parseAssignText(bad); }).find("--assign"), std::string::npos) << bad;
}

TEST(Assignment, ResolvesNamesGlobsMaterialsAndTheDefault) {
  const Scene scene = makeBuiltinScene("gallery");
  const Assignment a = resolveAssignment(
      scene, parseAssignText("mirror-back,mirror-left=planar;mirror-t*=depthmap:order=3;*=envmap"));
  ASSERT_EQ(a.parts.size(), 3u);
  EXPECT_EQ(namesOf(scene, a.parts[0]), (std::vector<std::string>{"mirror-back", "mirror-left"}));
  EXPECT_EQ(namesOf(scene, a.parts[1]), (std::vector<std::string>{"mirror-teapot"}));
  EXPECT_EQ(a.parts[1].order, 3);
  EXPECT_EQ(namesOf(scene, a.parts[2]),
            (std::vector<std::string>{"mirror-sphere", "concave-mirror"}));
  EXPECT_FALSE(a.parts[2].order.has_value());
  // A material name selects its instances; a default left with nothing to do is dropped.
  const std::string material =
      scene.materials[size_t(scene.instances[size_t(a.parts[1].reflectors[0])].material)].name;
  const Assignment m = resolveAssignment(scene, parseAssignText(material + "=zexel;*=planar"));
  size_t assigned = 0;
  for (const AssignedPart& p : m.parts) assigned += p.reflectors.size();
  EXPECT_EQ(assigned, scene.reflectorInstances().size());
  EXPECT_EQ(
      resolveAssignment(scene, parseAssignText("*=none;mirror*,concave*=planar")).parts.size(), 1u);
}

TEST(Assignment, MistakesNameTheEntryAndWhatExists) {
  const Scene scene = makeBuiltinScene("gallery");
  auto error = [&](const std::string& text) {
    return inputError([&] { resolveAssignment(scene, parseAssignText(text)); });
  };
  const std::string unknown_reflector = error("ball=planar;*=envmap");
  EXPECT_NE(unknown_reflector.find("'ball' names no reflector"), std::string::npos);
  EXPECT_NE(unknown_reflector.find("mirror-teapot"), std::string::npos) << unknown_reflector;
  EXPECT_NE(error("yellow-torus=planar;*=envmap").find("names no reflector"), std::string::npos);
  const std::string unknown_method = error("*=plane");
  EXPECT_NE(unknown_method.find("unknown method 'plane'"), std::string::npos);
  EXPECT_NE(unknown_method.find("envmap-box"), std::string::npos) << unknown_method;
  EXPECT_NE(error("*=raytrace").find("cannot be assigned"), std::string::npos);
  EXPECT_NE(error("*=mixed").find("cannot be assigned"), std::string::npos);
  const std::string param = error("*=planar:srdm-m=16");
  EXPECT_NE(param.find("no parameter --srdm-m"), std::string::npos) << param;
  EXPECT_NE(error("*=depthmap:srdm-m=0").find("out of range"), std::string::npos);
  EXPECT_NE(error("*=billboard:order=0").find("--order 0"), std::string::npos);
  const std::string twice = error("mirror-*=planar;mirror-back=none;*=envmap");
  EXPECT_NE(twice.find("'mirror-back' is already assigned by --assign entry 1"), std::string::npos)
      << twice;
  EXPECT_NE(error("*=planar;*=envmap").find("second default"), std::string::npos);
  const std::string left = error("mirror-back=planar");
  EXPECT_NE(left.find("no method to reflectors mirror-left, mirror-sphere"), std::string::npos)
      << left;
}

TEST(Assignment, ReassigningOneReflectorKeepsTheOthers) {
  const Scene scene = makeBuiltinScene("gallery");
  const int sphere = scene.reflectorInstances()[2];
  const auto rules =
      reassign(scene, parseAssignText("mirror-back,mirror-left=planar;*=envmap-box:order=3"),
               sphere, "depthmap");
  const Assignment a = resolveAssignment(scene, rules);
  EXPECT_EQ(methodOf(a, sphere), "depthmap");
  EXPECT_EQ(methodOf(a, scene.reflectorInstances()[0]), "planar");
  EXPECT_EQ(methodOf(a, scene.reflectorInstances()[3]), "envmap-box");
  EXPECT_EQ(a.parts[1].order, 3);  // the teapot and the concave mirror keep their entry's K
  EXPECT_THROW(reassign(scene, rules, sphere, "raytrace"), InputError);
}

TEST(Assignment, SceneFileReflectionsAreReadAndCheckedWithTheirPath) {
  const std::string head = R"({"materials": [{"name": "chrome", "type": "reflector"}],
    "meshes": [{"name": "b", "procedural": "sphere"}],
    "instances": [{"name": "ball", "mesh": "b", "material": "chrome"}], "reflections": )";
  const Scene s = parseSceneJson(
      "s.json", head + R"([{"reflectors": ["ball"], "method": "depthmap", "params": {"srdm-m": 16,
      "depth-step": 0.5, "billboard-objects": "all", "order": 3}}]})",
      "");
  ASSERT_EQ(s.reflections.size(), 1u);
  EXPECT_EQ(s.reflections[0].params.at("srdm-m"), "16");
  EXPECT_EQ(s.reflections[0].params.at("depth-step"), "0.5");
  EXPECT_EQ(s.reflections[0].where, "s.json: reflections[0]");
  const std::string unknown = inputError([&] {
    Scene bad =
        parseSceneJson("s.json", head + R"([{"reflectors": "chrome", "method": "x"}]})", "");
    resolveAssignment(bad, bad.reflections);
  });
  EXPECT_NE(unknown.find("s.json: reflections[0] 'chrome=x': unknown method 'x'"),
            std::string::npos)
      << unknown;
  for (const char* bad :
       {R"([{"method": "planar"}]})", R"([{"reflectors": [], "method": "planar"}]})",
        R"([{"reflectors": "*", "method": "planar", "size": 2}]})",
        R"([{"reflectors": "*", "method": "planar", "params": {"a": [1]}}]})",
        R"({"reflectors": "*"}})"})
    EXPECT_NE(inputError([&] { parseSceneJson("s.json", head + bad, ""); }).find("s.json"),
              std::string::npos)
        << bad;
}

}  // namespace
}  // namespace mirage
