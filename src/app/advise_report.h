// What `mirage advise` writes (docs/advise.md): advice.json, the assignment as scene JSON and as
// command-line flags, and an HTML report with each reflector's Pareto front as inline SVG.
#pragma once

#include <nlohmann/json.hpp>

#include "app/advise.h"

namespace mirage::app {

// {assignment, budget_ms, predicted: {psnr_reflector, ms}, measured: {...}, candidates: [...]}.
nlohmann::json adviceJson(const Advice& a, const std::string& scene_name);
// {"reflections": [...]}: the assignment as a scene file gives it.
nlohmann::json reflectionsJson(const std::vector<ReflectionRule>& rules);
// The report page.
std::string adviceHtml(const Advice& a, const std::string& scene_name);

// The candidates of one reflector on its Pareto front (no other candidate both cheaper and with
// less error), by cost.
std::vector<int> paretoFront(const std::vector<Measured>& measured);

}  // namespace mirage::app
