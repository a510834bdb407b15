// The method registry: adding a method is one line here (plus its folder).
#include <algorithm>

#include <fmt/ranges.h>

#include "core/error.h"
#include "methods/billboard/billboard_method.h"
#include "methods/depthmap/depthmap_method.h"
#include "methods/envmap/envmap_method.h"
#include "methods/hybrid/hybrid_method.h"
#include "methods/method.h"
#include "methods/mixed/mixed_method.h"
#include "methods/none/none_method.h"
#include "methods/planar/planar_method.h"
#include "methods/raytrace/raytrace_method.h"
#include "methods/ssr/ssr_method.h"
#include "methods/zexel/zexel_method.h"

namespace mirage {

namespace {

std::vector<MethodEntry> makeRegistry() {
  std::vector<MethodEntry> methods = {
      noneMethodEntry(),      envmapInfiniteMethodEntry(), envmapMethodEntry(),
      envmapBoxMethodEntry(), billboardMethodEntry(),      depthmapMethodEntry(),
      hybridMethodEntry(),    planarMethodEntry(),         zexelMethodEntry(),
      ssrMethodEntry(),       raytraceMethodEntry(),
  };
  // Last: it takes every other method's parameters.
  methods.push_back(mixedMethodEntry(methods));
  return methods;
}

}  // namespace

const std::vector<MethodEntry>& methodRegistry() {
  static const std::vector<MethodEntry> registry = makeRegistry();
  return registry;
}

std::vector<std::string> methodNames() {
  std::vector<std::string> names;
  for (const MethodEntry& e : methodRegistry()) names.push_back(e.info.name);
  return names;
}

const MethodEntry& findMethod(const std::string& name) {
  for (const MethodEntry& e : methodRegistry())
    if (e.info.name == name) return e;
  throwInput("unknown method '{}' (allowed: {})", name, fmt::join(methodNames(), ", "));
}

std::vector<std::string> parseMethodList(const std::string& list) {
  if (list == "all") {
    std::vector<std::string> out;
    for (const MethodEntry& e : methodRegistry())
      if (!e.info.needs_assignment) out.push_back(e.info.name);
    return out;
  }
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= list.size()) {
    size_t comma = list.find(',', start);
    std::string name =
        list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty())
      throwInput(
          "--methods '{}': empty method name (allowed: all, or a comma-separated list of {})", list,
          fmt::join(methodNames(), ", "));
    findMethod(name);
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::map<std::string, double> frameCounts(const MethodInfo& info,
                                          const std::map<std::string, double>& before,
                                          const std::map<std::string, double>& after) {
  std::map<std::string, double> out;
  auto value = [](const std::map<std::string, double>& m, const std::string& name) {
    auto it = m.find(name);
    return it == m.end() ? 0.0 : it->second;
  };
  for (const std::string& name : info.counters)
    out[name] = value(after, name) - value(before, name);
  for (const std::string& name : info.frame_stats)
    if (after.count(name)) out[name] = value(after, name);
  return out;
}

std::vector<ParamSpec> mergedParams(std::span<const MethodEntry> entries) {
  std::vector<ParamSpec> out;
  std::vector<std::string> declared_by;  // out[i]'s first method
  for (const MethodEntry& e : entries)
    for (const ParamSpec& p : e.info.params) {
      auto same_name = [&](const ParamSpec& q) { return q.name == p.name; };
      auto it = std::find_if(out.begin(), out.end(), same_name);
      if (it == out.end()) {
        out.push_back(p);
        declared_by.push_back(e.info.name);
      } else if (!(*it == p)) {
        detail::checkFailed(
            __FILE__, __LINE__, "same-named parameter specs are equal",
            fmt::format(": methods {} and {} declare --{} differently (a parameter of one name is "
                        "one spec: methods/probe_params.h)",
                        declared_by[size_t(it - out.begin())], e.info.name, p.name));
      }
    }
  return out;
}

std::vector<ParamSpec> allMethodParams() {
  return mergedParams(methodRegistry());
}

}  // namespace mirage
