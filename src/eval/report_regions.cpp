// The compare report's region parts: the reference's sampling and noise floor, the error per
// reflector (best method marked) and per cause (the cause image and where each method loses its
// decibels), in metrics.json and in the HTML page of both kinds of report.
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "eval/causes.h"
#include "eval/report_html.h"

namespace mirage::report_html {

namespace {

nlohmann::json regionJson(const RegionMetrics& r, bool quality) {
  nlohmann::json e;
  e["pixels"] = r.pixels;
  e["psnr"] = number(r.psnr);
  e["sse"] = number(r.sse);
  if (quality) {
    e["ssim"] = number(r.ssim);
    e["flip"] = number(r.flip);
  }
  return e;
}

nlohmann::json regionMapJson(const std::map<std::string, RegionMetrics>& regions, bool quality) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, r] : regions) out[name] = regionJson(r, quality);
  return out;
}

// The methods that are ranked (every one but the reference).
std::vector<const MethodReport*> ranked(const CompareReport& r) {
  std::vector<const MethodReport*> out;
  for (const MethodReport& m : r.methods)
    if (!isReference(r, m)) out.push_back(&m);
  return out;
}

std::string methodHeader(const std::vector<const MethodReport*>& methods) {
  std::string h;
  for (const MethodReport* m : methods) h += "<th>" + escape(m->name) + "</th>";
  return h;
}

double psnrOf(const MethodReport& m, const std::map<std::string, RegionMetrics> RegionSet::*map,
              const std::string& name) {
  auto it = (m.regions.*map).find(name);
  return it == (m.regions.*map).end() || it->second.pixels == 0 ? std::nan("") : it->second.psnr;
}

// One row per region `names[k]` of `member`: its label cells (`labels[k]`, HTML), its pixels
// (the most any method saw) and each method's PSNR on it, the best marked.
std::string psnrRows(const std::vector<const MethodReport*>& methods,
                     std::map<std::string, RegionMetrics> RegionSet::*member,
                     const std::vector<std::string>& names, const std::vector<std::string>& labels) {
  std::string rows;
  for (size_t k = 0; k < names.size(); ++k) {
    size_t pixels = 0;
    for (const MethodReport* m : methods)
      if (auto it = (m->regions.*member).find(names[k]); it != (m->regions.*member).end())
        pixels = std::max(pixels, it->second.pixels);
    double best = std::nan("");
    for (const MethodReport* m : methods) {
      double v = psnrOf(*m, member, names[k]);
      if (!std::isnan(v) && (std::isnan(best) || v > best)) best = v;
    }
    std::string row = fmt::format("<tr>{}<td>{}</td>", labels[k], pixels);
    for (const MethodReport* m : methods) {
      double v = psnrOf(*m, member, names[k]);
      row += fmt::format("<td{}>{}</td>", !std::isnan(v) && v == best ? " class=best" : "",
                         cell(v, "{:.2f}"));
    }
    rows += row + "</tr>\n";
  }
  return rows;
}

std::string reflectorTable(const CompareReport& r) {
  const auto methods = ranked(r);
  if (r.reflector_names.empty() || methods.empty()) return {};
  std::vector<std::string> labels;
  for (const std::string& name : r.reflector_names) labels.push_back("<td>" + escape(name) + "</td>");
  const std::string rows = psnrRows(methods, &RegionSet::reflectors, r.reflector_names, labels);
  return fmt::format(
      "<section id=reflectors><h2>Per reflector</h2><p class=d>Reflector PSNR (dB) of each "
      "method on each reflector's pixels (the reference's reflector ids); green: the best method "
      "for that reflector.</p>\n<table><thead><tr><th>reflector</th><th>pixels</th>{}</tr>"
      "</thead><tbody>\n{}</tbody></table></section>\n",
      methodHeader(methods), rows);
}

// The error per layer of the reflected scene and per diffuse object, each with its layer.
std::string layerTable(const CompareReport& r) {
  const auto methods = ranked(r);
  bool any = false;
  for (const MethodReport* m : methods) any = any || !m->regions.layers.empty();
  if (!any) return {};
  const std::vector<std::string> layers = {"environment", "object", "reflectors"};
  std::vector<std::string> labels, objects, object_labels;
  for (const std::string& layer : layers) labels.push_back("<td><b>" + layer + "</b></td><td></td>");
  for (const auto& [name, layer] : r.object_layers) {
    objects.push_back(name);
    object_labels.push_back("<td>" + escape(name) + "</td><td>" + escape(layer) + "</td>");
  }
  const std::string rows = psnrRows(methods, &RegionSet::layers, layers, labels) +
                           psnrRows(methods, &RegionSet::diffuse_objects, objects, object_labels);
  return fmt::format(
      "<section id=layers><h2>Per layer and object</h2><p class=d>PSNR (dB) on the reflector "
      "pixels whose reflected ray (the ray tracer's) meets each layer of the reflected scene "
      "first — the environment (the sky and the environment's instances), the objects, the "
      "reflectors (self, other, beyond the order) — then on those that meet each diffuse object, "
      "with the object's layer (docs/architecture.md, \"Layers\"); green: the best method.</p>\n"
      "<table><thead><tr><th>region</th><th>layer</th><th>pixels</th>{}</tr></thead><tbody>\n{}"
      "</tbody></table></section>\n",
      methodHeader(methods), rows);
}

std::string causeLegend() {
  std::string items;
  for (uint32_t label = 1; label <= kUnclassified; ++label) {
    vec3 c = causeColour(label) * 255.0f;
    items += fmt::format(
        "<span style=\"display:inline-block;margin-right:1em\"><span style=\"display:inline-block;"
        "width:1em;height:1em;vertical-align:middle;background:rgb({},{},{})\"></span> {}</span>",
        int(std::lround(c.x)), int(std::lround(c.y)), int(std::lround(c.z)), causeName(label));
  }
  return items;
}

// Share of each method's squared error on reflector pixels per cause, and each cause's PSNR.
std::string causeTable(const std::vector<const MethodReport*>& methods) {
  std::string rows;
  for (uint32_t label = 1; label <= kUnclassified; ++label) {
    const std::string name = causeName(label);
    size_t pixels = 0;
    for (const MethodReport* m : methods)
      if (auto it = m->regions.causes.find(name); it != m->regions.causes.end())
        pixels = std::max(pixels, it->second.pixels);
    if (pixels == 0) continue;
    std::string row = fmt::format("<tr><td>{}</td><td>{}</td>", name, pixels);
    for (const MethodReport* m : methods) {
      double total = 0.0, own = 0.0, psnr = std::nan("");
      for (const auto& [cause, c] : m->regions.causes) total += c.sse;
      if (auto it = m->regions.causes.find(name); it != m->regions.causes.end())
        own = it->second.sse, psnr = it->second.psnr;
      row += fmt::format("<td>{} <small>({} dB)</small></td>",
                         total > 0.0 ? fmt::format("{:.1f}%", 100.0 * own / total) : "&ndash;",
                         cell(psnr, "{:.1f}"));
    }
    rows += row + "</tr>\n";
  }
  std::string mixed = "<tr><td><i>mixed</i></td><td>";
  size_t mixed_pixels = 0;
  for (const MethodReport* m : methods)
    mixed_pixels = std::max(mixed_pixels, m->regions.mixed.pixels);
  mixed += fmt::format("{}</td>", mixed_pixels);
  for (const MethodReport* m : methods) {
    double total = 0.0;
    for (const auto& [cause, c] : m->regions.causes) total += c.sse;
    mixed += fmt::format(
        "<td>{} <small>({} dB)</small></td>",
        total > 0.0 ? fmt::format("{:.1f}%", 100.0 * m->regions.mixed.sse / total) : "&ndash;",
        cell(m->regions.mixed.pixels ? m->regions.mixed.psnr : std::nan(""), "{:.1f}"));
  }
  rows += mixed + "</tr>\n";
  return fmt::format(
      "<table><thead><tr><th>cause</th><th>pixels</th>{}</tr></thead><tbody>\n{}</tbody></table>",
      methodHeader(methods), rows);
}

std::string causeSection(const CompareReport& r) {
  const auto methods = ranked(r);
  bool any = false;
  for (const MethodReport* m : methods) any = any || m->regions.has_causes;
  if (!any) return {};
  std::string image =
      r.cause_image.empty()
          ? ""
          : fmt::format(
                "<figure style=\"max-width:640px\"><img src=\"{}\" alt=\"error causes\">"
                "<figcaption>{}<br>darker: mixed pixels; grey: not a reflector"
                "</figcaption></figure>\n",
                escape(r.cause_image), causeLegend());
  return fmt::format(
      "<section id=causes><h2>Where the error comes from</h2><p class=d>Each reflector pixel is "
      "classified by what the ray tracer's reflected ray meets first: the environment, a diffuse "
      "object, the reflector itself, another reflector, or a reflector past the last allowed "
      "bounce (beyond_order: every method shows its base colour there). Under --ssaa a pixel "
      "takes the majority of its sub-pixels; <i>mixed</i> counts the pixels whose sub-pixels met "
      "different things (also counted under their majority). Each cell: the share of the "
      "method's squared error on reflector pixels, and the PSNR on that cause's pixels.</p>\n"
      "{}{}</section>\n",
      image, causeTable(methods));
}

}  // namespace

nlohmann::json regionsJson(const RegionSet& regions) {
  nlohmann::json e;
  e["reflectors"] = regionMapJson(regions.reflectors, true);
  if (regions.has_causes) {
    e["causes"] = regionMapJson(regions.causes, false);
    e["diffuse_objects"] = regionMapJson(regions.diffuse_objects, false);
    e["layers"] = regionMapJson(regions.layers, false);
    e["mixed"] = regionJson(regions.mixed, false);
  }
  return e;
}

nlohmann::json referenceJson(const CompareReport& r) {
  nlohmann::json e;
  e["method"] = r.reference;
  e["ssaa"] = r.reference_info.ssaa;
  e["checked"] = r.reference_info.checked;
  if (r.reference_info.checked) {
    e["converged_spp"] = r.reference_info.converged_spp;
    e["noise_floor_psnr"] = number(r.reference_info.noise_floor_psnr);
    e["noise_floor_psnr_reflector"] = number(r.reference_info.noise_floor_psnr_reflector);
  }
  return e;
}

std::string samplingNote(const CompareReport& r) {
  const ReferenceInfo& info = r.reference_info;
  std::string note = fmt::format(
      "<p class=d>Sampling: every method and the reference render {0}&times;{0} sub-pixels per "
      "output pixel (<code>--ssaa {0}</code>: a regular grid, box-filtered in linear radiance "
      "before the display transform), so aliasing is alike on both sides. Times: {1}.</p>",
      info.ssaa, escape(r.timing));
  if (info.checked)
    note += fmt::format(
        "<p class=d><b>Noise floor</b>: the reference is {0} dB (reflector pixels: <b>{1} dB</b>) "
        "from a converged image of {2} stratified samples a pixel. A method's reflector PSNR "
        "near or above {1} dB is as close as this reference can tell; differences between "
        "methods up there are the reference's own sampling, not theirs.</p>",
        cell(info.noise_floor_psnr, "{:.2f}"), cell(info.noise_floor_psnr_reflector, "{:.2f}"),
        info.converged_spp);
  return note;
}

std::string regionSections(const CompareReport& r) {
  return reflectorTable(r) + causeSection(r) + layerTable(r);
}

}  // namespace mirage::report_html
