// Reflection assignments (docs/advise.md): which method draws which reflector, from a scene
// file's "reflections" or `--assign`, resolved against the scene and the method registry. Method
// `mixed` draws a frame by one; `mirage advise` chooses one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace mirage {

struct MethodInfo;

// Method `mixed`'s parameter that holds an assignment as `--assign` text.
inline constexpr const char* kAssignParam = "assign";

// Whether a method can draw some reflectors of a frame (not `raytrace` or `mixed`, which draw
// whole frames).
bool assignable(const MethodInfo& info);

// "depthmap:srdm-m=16": a method and parameter values as an entry of `--assign` writes them.
std::string methodText(const std::string& method, const std::map<std::string, std::string>& params);

// One entry of a resolved assignment: a method and what it draws.
struct AssignedPart {
  std::string method;
  std::map<std::string, std::string> params;  // the entry's own values, checked (no "order")
  std::optional<int> order;                   // the entry's K; empty: the frame's
  std::vector<int> reflectors;                // reflector instances, in scene order (not empty)
  std::string label;                          // the entry as `--assign` writes it
};

struct Assignment {
  std::vector<AssignedPart> parts;  // in the order given; every reflector in exactly one
};

// `--assign 'mirror*=planar;ball=depthmap:srdm-m=16;*=envmap-box'`: entries separated by ';',
// each `names=method` then `:param=value` (or `,param=value`) for each parameter; `names` is a
// comma-separated list of reflector or material names or globs. Throws InputError on a
// malformed entry, naming it.
std::vector<ReflectionRule> parseAssignText(const std::string& text);

// The rules back as `--assign` text, and one rule's entry.
std::string assignText(const std::vector<ReflectionRule>& rules);
std::string ruleText(const ReflectionRule& rule);

// Resolves `rules` for `scene`: each rule's reflectors by instance or material name (globs as
// fnmatch), "*" alone the default entry for the reflectors no other entry names. Throws InputError
// naming the rule (its `where`) and what exists when a method is unknown or cannot be assigned
// (`raytrace`, `mixed`), a parameter is unknown or out of range, a name matches no reflector, a
// reflector is matched by two entries, or a reflector is left without a method.
Assignment resolveAssignment(const Scene& scene, const std::vector<ReflectionRule>& rules);

// `rules` with reflector `instance` given to `method` (an entry of its own, default parameters)
// and the others as before: one entry per part, listing its reflectors by name (the viewer's
// live reassignment).
std::vector<ReflectionRule> reassign(const Scene& scene, const std::vector<ReflectionRule>& rules,
                                     int instance, const std::string& method);
// The method `assignment` gives reflector `instance`, or empty.
std::string methodOf(const Assignment& assignment, int instance);

// The assignment a method would draw alone: every reflector of `scene` by `method`.
std::vector<ReflectionRule> singleMethodRules(const std::string& method,
                                              const std::map<std::string, std::string>& params);

}  // namespace mirage
