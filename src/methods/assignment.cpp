#include "methods/assignment.h"

#include <fnmatch.h>

#include <algorithm>

#include <fmt/ranges.h>

#include "core/error.h"
#include "methods/method.h"

namespace mirage {

namespace {

std::vector<std::string> split(const std::string& text, const std::string& separators) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || separators.find(text[i]) != std::string::npos) {
      out.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  return out;
}

bool isDefault(const ReflectionRule& rule) {
  return rule.reflectors.size() == 1 && rule.reflectors.front() == "*";
}

bool matches(const std::string& pattern, const std::string& name) {
  return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
}

// Whether `pattern` names reflector `instance`, by its own name or its material's.
bool names(const Scene& scene, const std::string& pattern, int instance) {
  const Instance& inst = scene.instances[size_t(instance)];
  return matches(pattern, inst.name) ||
         matches(pattern, scene.materials[size_t(inst.material)].name);
}

std::vector<std::string> reflectorNames(const Scene& scene) {
  std::vector<std::string> out;
  for (int i : scene.reflectorInstances()) out.push_back(scene.instances[size_t(i)].name);
  return out;
}

// Checks the rule's method and parameters and fills the part's method, params and order.
AssignedPart checkedPart(const ReflectionRule& rule) {
  AssignedPart part;
  part.label = ruleText(rule);
  const std::string who = fmt::format("{} '{}'", rule.where, part.label);
  const MethodEntry* entry = nullptr;
  try {
    entry = &findMethod(rule.method);
  } catch (const InputError& e) {
    throwInput("{}: {}", who, e.what());
  }
  if (!assignable(entry->info))
    throwInput("{}: method '{}' cannot be assigned to reflectors (it draws whole frames)", who,
               rule.method);
  part.method = rule.method;
  for (const auto& [name, value] : rule.params) {
    if (name != "order") {
      part.params[name] = value;
      continue;
    }
    ParamSpec spec = ParamSpec::integer("order", entry->info.min_order, kMaxOrder, 2,
                                        "the entry's reflection order");
    try {
      checkParam(spec, value);
    } catch (const InputError& e) {
      throwInput("{}: {}", who, e.what());
    }
    part.order = std::stoi(value);
  }
  try {
    ParamValues::validate(entry->info.params, part.params, "method '" + rule.method + "'");
  } catch (const InputError& e) {
    throwInput("{}: {}; an entry may also set order", who, e.what());
  }
  return part;
}

}  // namespace

std::vector<ReflectionRule> parseAssignText(const std::string& text) {
  std::vector<ReflectionRule> rules;
  for (const std::string& entry : split(text, ";")) {
    if (entry.empty()) continue;  // "a=b;" and "a=b;;c=d" are fine
    ReflectionRule rule;
    rule.where = fmt::format("--assign entry {}", rules.size() + 1);
    const size_t eq = entry.find('=');
    if (eq == std::string::npos || eq == 0)
      throwInput("--assign '{}': expected NAMES=METHOD[:PARAM=VALUE...], e.g. 'mirror*=planar'",
                 entry);
    rule.reflectors = split(entry.substr(0, eq), ",");
    const std::vector<std::string> fields = split(entry.substr(eq + 1), ":,");
    rule.method = fields.front();
    for (size_t i = 1; i < fields.size(); ++i) {
      const size_t p = fields[i].find('=');
      if (p == std::string::npos || p == 0 || p + 1 == fields[i].size())
        throwInput("--assign '{}': parameter '{}' is not NAME=VALUE", entry, fields[i]);
      rule.params[fields[i].substr(0, p)] = fields[i].substr(p + 1);
    }
    for (const std::string& name : rule.reflectors)
      if (name.empty()) throwInput("--assign '{}': an empty reflector name", entry);
    if (rule.method.empty()) throwInput("--assign '{}': no method after '='", entry);
    rules.push_back(std::move(rule));
  }
  if (rules.empty()) throwInput("--assign '{}': no entries (expected NAMES=METHOD;...)", text);
  return rules;
}

bool assignable(const MethodInfo& info) {
  return info.gpu && !info.needs_assignment;
}

std::string methodText(const std::string& method,
                       const std::map<std::string, std::string>& params) {
  std::string out = method;
  for (const auto& [name, value] : params) out += ":" + name + "=" + value;
  return out;
}

std::string ruleText(const ReflectionRule& rule) {
  return fmt::format("{}={}", fmt::join(rule.reflectors, ","),
                     methodText(rule.method, rule.params));
}

std::string assignText(const std::vector<ReflectionRule>& rules) {
  std::vector<std::string> entries;
  for (const ReflectionRule& rule : rules) entries.push_back(ruleText(rule));
  return fmt::format("{}", fmt::join(entries, ";"));
}

Assignment resolveAssignment(const Scene& scene, const std::vector<ReflectionRule>& rules) {
  const std::vector<int> reflectors = scene.reflectorInstances();
  std::vector<int> owner(scene.instances.size(), -1);  // the rule of each reflector
  Assignment out;
  int default_rule = -1;
  for (size_t r = 0; r < rules.size(); ++r) {
    const ReflectionRule& rule = rules[r];
    AssignedPart part = checkedPart(rule);
    out.parts.push_back(std::move(part));
    if (isDefault(rule)) {
      if (default_rule >= 0)
        throwInput("{} '{}': a second default entry ('*'; the first is {})", rule.where,
                   ruleText(rule), rules[size_t(default_rule)].where);
      default_rule = int(r);
      continue;
    }
    for (const std::string& pattern : rule.reflectors) {
      bool any = false;
      for (int i : reflectors) {
        if (!names(scene, pattern, i)) continue;
        any = true;
        if (owner[size_t(i)] >= 0 && owner[size_t(i)] != int(r))
          throwInput("{} '{}': reflector '{}' is already assigned by {} '{}'", rule.where,
                     ruleText(rule), scene.instances[size_t(i)].name,
                     rules[size_t(owner[size_t(i)])].where,
                     ruleText(rules[size_t(owner[size_t(i)])]));
        owner[size_t(i)] = int(r);
      }
      if (!any)
        throwInput("{} '{}': '{}' names no reflector of scene '{}' (its reflectors: {})",
                   rule.where, ruleText(rule), pattern, scene.name,
                   fmt::join(reflectorNames(scene), ", "));
    }
  }
  std::vector<std::string> left;
  for (int i : reflectors) {
    if (owner[size_t(i)] < 0 && default_rule >= 0) owner[size_t(i)] = default_rule;
    if (owner[size_t(i)] < 0)
      left.push_back(scene.instances[size_t(i)].name);
    else
      out.parts[size_t(owner[size_t(i)])].reflectors.push_back(i);
  }
  if (!left.empty())
    throwInput(
        "the assignment gives no method to reflector{} {} (add a default entry, e.g. "
        "'*=envmap')",
        left.size() == 1 ? "" : "s", fmt::join(left, ", "));
  std::erase_if(out.parts, [](const AssignedPart& p) { return p.reflectors.empty(); });
  return out;
}

std::vector<ReflectionRule> reassign(const Scene& scene, const std::vector<ReflectionRule>& rules,
                                     int instance, const std::string& method) {
  std::vector<ReflectionRule> out;
  for (const AssignedPart& part : resolveAssignment(scene, rules).parts) {
    ReflectionRule rule{{}, part.method, part.params, "the viewer's assignment"};
    if (part.order) rule.params["order"] = std::to_string(*part.order);
    for (int i : part.reflectors)
      if (i != instance) rule.reflectors.push_back(scene.instances[size_t(i)].name);
    if (!rule.reflectors.empty()) out.push_back(std::move(rule));
  }
  out.push_back({{scene.instances[size_t(instance)].name}, method, {}, "the viewer's assignment"});
  resolveAssignment(scene, out);  // the method is one that can be assigned
  return out;
}

std::string methodOf(const Assignment& assignment, int instance) {
  for (const AssignedPart& part : assignment.parts)
    if (std::find(part.reflectors.begin(), part.reflectors.end(), instance) !=
        part.reflectors.end())
      return part.method;
  return {};
}

std::vector<ReflectionRule> singleMethodRules(const std::string& method,
                                              const std::map<std::string, std::string>& params) {
  return {ReflectionRule{{"*"}, method, params, "the single-method assignment"}};
}

}  // namespace mirage
