// The methods' parameters as the command line and the viewer see them: a parameter that several
// methods list (--envmap-size, --proxy) is one spec, and a registry whose methods declare one
// name differently is refused rather than resolved by whichever method comes first.
#include <map>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "methods/method.h"

namespace mirage {
namespace {

TEST(MethodParams, SameNamedParametersOfTheRegistryAreIdentical) {
  std::map<std::string, std::pair<std::string, ParamSpec>> first;  // name -> (method, spec)
  int shared = 0;
  for (const MethodEntry& e : methodRegistry())
    for (const ParamSpec& p : e.info.params) {
      auto [it, inserted] = first.try_emplace(p.name, e.info.name, p);
      if (inserted) continue;
      ++shared;
      const ParamSpec& q = it->second.second;
      const std::string who = it->second.first + " and " + e.info.name + ": --" + p.name;
      EXPECT_EQ(p.type, q.type) << who;
      EXPECT_EQ(p.min, q.min) << who;
      EXPECT_EQ(p.max, q.max) << who;
      EXPECT_EQ(p.default_value, q.default_value) << who;
      EXPECT_EQ(p.choices, q.choices) << who;
      EXPECT_EQ(p.help, q.help) << who;
    }
  // envmap-size is listed by envmap, envmap-box, billboard, depthmap, hybrid and ssr; proxy by
  // envmap-box and ssr: the check above compared something.
  EXPECT_GE(shared, 6);
  EXPECT_NO_THROW(allMethodParams());
  EXPECT_EQ(allMethodParams().size(), first.size());
}

TEST(MethodParams, DifferingSpecsOfOneNameAreRefusedNamingBothMethods) {
  auto entry = [](std::string name, ParamSpec spec) {
    MethodEntry e;
    e.info.name = std::move(name);
    e.info.params = {std::move(spec)};
    return e;
  };
  const std::vector<MethodEntry> alike = {
      entry("a", ParamSpec::integer("size", 8, 2048, 256, "face size")),
      entry("b", ParamSpec::integer("size", 8, 2048, 256, "face size"))};
  EXPECT_EQ(mergedParams(alike).size(), 1u);

  const std::vector<MethodEntry> differing = {
      entry("a", ParamSpec::integer("size", 8, 2048, 256, "face size")),
      entry("b", ParamSpec::integer("size", 8, 2048, 128, "face size"))};
  try {
    mergedParams(differing);
    FAIL() << "a second, different spec of --size was accepted";
  } catch (const RuntimeError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("methods a and b"), std::string::npos) << what;
    EXPECT_NE(what.find("--size"), std::string::npos) << what;
    EXPECT_NE(what.find("internal error: "), std::string::npos) << what;
  }
}

enum class Fruit { kApple, kPear };
constexpr Choice<Fruit> kFruits[] = {{"apple", Fruit::kApple}, {"pear", Fruit::kPear}};

TEST(MethodParams, ChoicesAreReadThroughTheirTable) {
  const std::vector<ParamSpec> specs = {
      ParamSpec::choice<Fruit>("fruit", kFruits, Fruit::kPear, "a fruit"),
      ParamSpec::choice("switch", {"on", "off"}, "on", "a switch")};
  EXPECT_EQ(specs[0].choices, (std::vector<std::string>{"apple", "pear"}));
  EXPECT_EQ(specs[0].default_value, "pear");
  const ParamValues defaults = ParamValues::validate(specs, {}, "test");
  EXPECT_EQ(defaults.choice<Fruit>("fruit", kFruits), Fruit::kPear);
  EXPECT_TRUE(defaults.on("switch"));
  const ParamValues given =
      ParamValues::validate(specs, {{"fruit", "apple"}, {"switch", "off"}}, "test");
  EXPECT_EQ(given.choice<Fruit>("fruit", kFruits), Fruit::kApple);
  EXPECT_FALSE(given.on("switch"));
  // A table that lacks a value the spec allows is a bug of the method: an internal error.
  constexpr Choice<Fruit> kApplesOnly[] = {{"apple", Fruit::kApple}};
  EXPECT_THROW(defaults.choice<Fruit>("fruit", kApplesOnly), RuntimeError);
  EXPECT_THROW(defaults.on("fruit"), RuntimeError);
}

}  // namespace
}  // namespace mirage
