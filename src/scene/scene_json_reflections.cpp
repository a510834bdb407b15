// The top-level "reflections" of the scene format (docs/scene-format.md): which method draws
// which reflector. Checked here for shape and types; the names of reflectors, methods and
// parameters are checked against the scene and the method registry when the scene is used
// (methods/assignment.h), where the messages can list what exists.
#include "scene/scene_json_internal.h"

namespace mirage::scene_json {

namespace {

// A parameter's value as the text the command line would give: numbers as written (integers
// without a decimal point), strings as they are, true/false as on/off.
std::string paramText(const Field& value) {
  const Json& j = value.json();
  if (j.is_number_integer()) return std::to_string(j.get<long long>());
  if (j.is_number()) return fmt::format("{:g}", j.get<double>());
  if (j.is_boolean()) return j.get<bool>() ? "on" : "off";
  if (j.is_string()) return value.string();
  value.fail("= {}: expected a number, a string or true/false", value.describe());
}

std::vector<std::string> reflectorPatterns(const Field& f) {
  std::vector<std::string> out;
  if (f.json().is_string()) {
    out.push_back(f.string());
  } else if (f.json().is_array()) {
    for (const Field& item : f.items()) out.push_back(item.string());
    if (out.empty()) f.fail("is empty: name at least one reflector, material or glob");
  } else {
    f.fail("= {}: expected a name or glob, or a list of them", f.describe());
  }
  return out;
}

}  // namespace

std::vector<ReflectionRule> parseReflections(const Field& list) {
  std::vector<ReflectionRule> rules;
  for (const Field& f : list.items()) {
    f.allowKeys({"reflectors", "method", "params"}, "a reflections entry");
    ReflectionRule rule;
    rule.where = f.where();
    rule.reflectors = reflectorPatterns(f.required("reflectors"));
    rule.method = f.required("method").string();
    if (auto params = f.optional("params")) {
      params->requireObject("the parameters of a reflections entry");
      for (const auto& [name, value] : params->json().items())
        rule.params[name] = paramText(Field(f.file(), value, params->path() + "." + name));
    }
    rules.push_back(std::move(rule));
  }
  return rules;
}

}  // namespace mirage::scene_json
