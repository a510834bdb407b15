#include "app/advise_report.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "methods/assignment.h"

namespace mirage::app {

namespace {

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// A reflector's PSNR from its own summed error and pixels.
double reflectorPsnr(double sse, size_t pixels) {
  return pixels == 0 ? NAN : 10.0 * std::log10(double(pixels) / std::max(sse, 1e-30));
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// Frame time against PSNR, one dot per candidate, the front joined and the chosen one ringed.
std::string paretoSvg(const Advice& a, size_t r) {
  constexpr double kW = 420, kH = 260, kLeft = 50, kBottom = 36, kTop = 10, kRight = 10;
  const auto& m = a.measured[r];
  double lo_ms = 1e300, hi_ms = 0, lo_db = 1e300, hi_db = -1e300;
  for (const Measured& x : m) {
    const double db = reflectorPsnr(x.sse, a.pixels[r]);
    lo_ms = std::min(lo_ms, x.part_ms), hi_ms = std::max(hi_ms, x.part_ms);
    lo_db = std::min(lo_db, db), hi_db = std::max(hi_db, db);
  }
  // A log axis for time: the parts span three orders of magnitude.
  const double l0 = std::log10(std::max(lo_ms, 1e-3)), l1 = std::log10(std::max(hi_ms, 1e-2));
  auto px = [&](double ms) {
    const double t = (std::log10(std::max(ms, 1e-3)) - l0) / std::max(l1 - l0, 1e-6);
    return kLeft + t * (kW - kLeft - kRight);
  };
  auto py = [&](double db) {
    return kTop + (1.0 - (db - lo_db) / std::max(hi_db - lo_db, 1e-6)) * (kH - kTop - kBottom);
  };
  std::string s = fmt::format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' font-size='10'>"
      "<rect x='{}' y='{}' width='{}' height='{}' fill='none' stroke='#999'/>",
      kW, kH, kLeft, kTop, kW - kLeft - kRight, kH - kTop - kBottom);
  s += fmt::format(
      "<text x='{}' y='{}'>{:.3g} ms</text><text x='{}' y='{}' text-anchor='end'>"
      "{:.3g} ms</text><text x='{}' y='{}' text-anchor='middle'>part of the frame "
      "(ms, log)</text>",
      kLeft, kH - 22, lo_ms, kW - kRight, kH - 22, hi_ms, (kW + kLeft) / 2, kH - 6);
  s += fmt::format(
      "<text x='2' y='{}'>{:.1f}</text><text x='2' y='{}'>{:.1f}</text>"
      "<text x='2' y='{}'>dB</text>",
      kTop + 8, hi_db, kH - kBottom, lo_db, (kH - kBottom) / 2);
  std::string line;
  for (int c : paretoFront(m))
    line += fmt::format("{:.1f},{:.1f} ", px(m[size_t(c)].part_ms),
                        py(reflectorPsnr(m[size_t(c)].sse, a.pixels[r])));
  s += "<polyline fill='none' stroke='#3a7' points='" + line + "'/>";
  for (size_t c = 0; c < m.size(); ++c) {
    const double x = px(m[c].part_ms), y = py(reflectorPsnr(m[c].sse, a.pixels[r]));
    s += fmt::format(
        "<circle cx='{:.1f}' cy='{:.1f}' r='3' fill='#357'><title>{}: {:.2f} ms, "
        "{:.2f} dB</title></circle>",
        x, y, escape(a.candidates[c].label), m[c].part_ms, reflectorPsnr(m[c].sse, a.pixels[r]));
    if (a.chosen[r] == int(c))
      s += fmt::format(
          "<circle cx='{:.1f}' cy='{:.1f}' r='7' fill='none' stroke='#c33'/>"
          "<text x='{:.1f}' y='{:.1f}' fill='#c33'>{}</text>",
          x, y, x + 8, y - 6, escape(a.candidates[c].label));
  }
  return s + "</svg>";
}

// The best single method: the candidate with the least error over every reflector, of all and
// of those within the budget.
int bestSingle(const Advice& a, bool within_budget) {
  int best = -1;
  for (size_t c = 0; c < a.candidates.size(); ++c) {
    if (within_budget && a.single_ms[c] > a.budget_ms) continue;
    if (best < 0 || a.single_sse[c] < a.single_sse[size_t(best)]) best = int(c);
  }
  return best;
}

nlohmann::json singleJson(const Advice& a, int c) {
  if (c < 0) return nullptr;
  return {{"candidate", a.candidates[size_t(c)].label},
          {"psnr_reflector", number(a.psnr(a.single_sse[size_t(c)]))},
          {"ms", a.single_ms[size_t(c)]}};
}

}  // namespace

std::vector<int> paretoFront(const std::vector<Measured>& measured) {
  std::vector<int> order(measured.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    const Measured &a = measured[size_t(x)], &b = measured[size_t(y)];
    return a.part_ms != b.part_ms ? a.part_ms < b.part_ms : a.sse < b.sse;
  });
  std::vector<int> front;
  double least = INFINITY;
  for (int i : order)
    if (measured[size_t(i)].sse < least) {
      least = measured[size_t(i)].sse;
      front.push_back(i);
    }
  return front;
}

nlohmann::json reflectionsJson(const std::vector<ReflectionRule>& rules) {
  nlohmann::json list = nlohmann::json::array();
  for (const ReflectionRule& r : rules) {
    nlohmann::json e = {{"reflectors", r.reflectors}, {"method", r.method}};
    if (!r.params.empty()) e["params"] = r.params;
    list.push_back(e);
  }
  return {{"reflections", list}};
}

nlohmann::json adviceJson(const Advice& a, const std::string& scene_name) {
  nlohmann::json j;
  j["scene"] = scene_name;
  j["assignment"] = assignText(a.rules);
  j["reflections"] = reflectionsJson(a.rules)["reflections"];
  j["budget_ms"] = a.budget_ms;
  j["fits"] = a.fits;
  j["none_ms"] = a.none_ms;
  j["base_ms"] = a.base_ms;
  j["max_entries"] = kMaxAdviseEntries;
  j["predicted"] = {{"psnr_reflector", number(a.psnr(a.predicted_sse))}, {"ms", a.predicted_ms}};
  j["measured"] = {{"psnr_reflector", number(a.psnr(a.measured_sse))},
                   {"ms", a.measured_ms},
                   {"within_budget", a.measured_ms <= a.budget_ms}};
  j["best_single"] = singleJson(a, bestSingle(a, false));
  j["best_single_within_budget"] = singleJson(a, bestSingle(a, true));
  nlohmann::json candidates = nlohmann::json::array();
  for (size_t r = 0; r < a.reflectors.size(); ++r)
    for (size_t c = 0; c < a.candidates.size(); ++c)
      candidates.push_back(
          {{"reflector", a.reflectors[r]},
           {"candidate", a.candidates[c].label},
           {"pixels", a.pixels[r]},
           {"sse", a.measured[r][c].sse},
           {"psnr_reflector", number(reflectorPsnr(a.measured[r][c].sse, a.pixels[r]))},
           {"part_ms", a.measured[r][c].part_ms},
           {"chosen", a.chosen[r] == int(c)}});
  j["candidates"] = candidates;
  nlohmann::json singles = nlohmann::json::array();
  for (size_t c = 0; c < a.candidates.size(); ++c) {
    singles.push_back(singleJson(a, int(c)));
    singles.back()["entry_overhead_ms"] = a.fixed_ms[c];
  }
  j["single_methods"] = singles;
  nlohmann::json failed = nlohmann::json::array();
  for (const FailedCandidate& f : a.failed)
    failed.push_back({{"candidate", f.label}, {"reason", f.reason}});
  j["failed"] = failed;
  return j;
}

std::string adviceHtml(const Advice& a, const std::string& scene_name) {
  std::string h = "<!doctype html><html><head><meta charset='utf-8'><title>mirage advise: " +
                  escape(scene_name) +
                  "</title><style>body{font-family:sans-serif;margin:2em}td,th{padding:2px 8px;"
                  "text-align:right}figure{display:inline-block;margin:1em}</style></head><body>";
  h += "<h1>advise: " + escape(scene_name) + "</h1>";
  h += fmt::format("<p>budget {:.2f} ms (the none frame: {:.2f} ms); {}</p>", a.budget_ms,
                   a.none_ms, a.fits ? "the assignment fits" : "<b>nothing fits</b>: the cheapest");
  h += "<p><code>--method mixed --assign '" + escape(assignText(a.rules)) + "'</code></p>";
  h += "<table><tr><th></th><th>reflector PSNR (dB)</th><th>frame (ms)</th></tr>";
  auto row = [&](const std::string& what, double sse, double ms) {
    h += fmt::format("<tr><td style='text-align:left'>{}</td><td>{:.2f}</td><td>{:.2f}</td></tr>",
                     escape(what), a.psnr(sse), ms);
  };
  row("composite, predicted", a.predicted_sse, a.predicted_ms);
  row("composite, measured", a.measured_sse, a.measured_ms);
  for (bool within : {false, true})
    if (const int c = bestSingle(a, within); c >= 0)
      row(std::string("best single method") + (within ? " within the budget: " : ": ") +
              a.candidates[size_t(c)].label,
          a.single_sse[size_t(c)], a.single_ms[size_t(c)]);
  h += "</table>";
  if (!a.failed.empty()) {
    h += "<h2>Candidates that failed (left out of the choice)</h2><table>";
    for (const FailedCandidate& f : a.failed)
      h += "<tr><td style='text-align:left'>" + escape(f.label) +
           "</td><td style='text-align:left'>" + escape(f.reason) + "</td></tr>";
    h += "</table>";
  }
  h += "<h2>Each reflector's candidates (the chosen one ringed, the front in green)</h2>";
  for (size_t r = 0; r < a.reflectors.size(); ++r)
    h += "<figure>" + paretoSvg(a, r) + "<figcaption>" + escape(a.reflectors[r]) +
         fmt::format(" ({} pixels)", a.pixels[r]) + "</figcaption></figure>";
  return h + "</body></html>\n";
}

}  // namespace mirage::app
