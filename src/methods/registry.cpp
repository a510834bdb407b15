// The method registry: adding a method is one line here (plus its folder).
#include <algorithm>

#include <fmt/ranges.h>

#include "core/error.h"
#include "methods/billboard/billboard_method.h"
#include "methods/depthmap/depthmap_method.h"
#include "methods/envmap/envmap_method.h"
#include "methods/hybrid/hybrid_method.h"
#include "methods/method.h"
#include "methods/none/none_method.h"
#include "methods/planar/planar_method.h"
#include "methods/raytrace/raytrace_method.h"
#include "methods/ssr/ssr_method.h"
#include "methods/zexel/zexel_method.h"

namespace mirage {

const std::vector<MethodEntry>& methodRegistry() {
  static const std::vector<MethodEntry> registry = {
      noneMethodEntry(),      envmapInfiniteMethodEntry(), envmapMethodEntry(),
      envmapBoxMethodEntry(), billboardMethodEntry(),      depthmapMethodEntry(),
      hybridMethodEntry(),    planarMethodEntry(),         zexelMethodEntry(),
      ssrMethodEntry(),       raytraceMethodEntry(),
  };
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
  if (list == "all") return methodNames();
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

std::vector<ParamSpec> allMethodParams() {
  std::vector<ParamSpec> out;
  for (const MethodEntry& e : methodRegistry())
    for (const ParamSpec& p : e.info.params) {
      bool seen = false;
      for (const ParamSpec& q : out) seen = seen || q.name == p.name;
      if (!seen) out.push_back(p);
    }
  return out;
}

}  // namespace mirage
