// The compare report of the frames along a camera path (`mirage compare --path-frames N`): per
// method the mean and the worst frame of each figure, a table of the reflector PSNR frame by
// frame, and the images of the first, middle and last frame only, to keep the report small.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "eval/report.h"
#include "eval/report_html.h"

namespace mirage {

namespace {

// Fields of ImageMetrics that are averaged, with which way is better.
struct Figure {
  double ImageMetrics::*field;
  bool higher_is_better;
};
constexpr Figure kFigures[] = {
    {&ImageMetrics::psnr, true},  {&ImageMetrics::psnr_reflector, true},
    {&ImageMetrics::ssim, true},  {&ImageMetrics::ssim_reflector, true},
    {&ImageMetrics::flip, false}, {&ImageMetrics::flip_reflector, false},
};

}  // namespace

ImageMetrics meanMetrics(const std::vector<ImageMetrics>& frames) {
  ImageMetrics out;
  for (const Figure& f : kFigures) {
    double sum = 0.0;
    int n = 0;
    for (const ImageMetrics& m : frames)
      if (!std::isnan(m.*f.field)) sum += m.*f.field, ++n;
    out.*f.field = n > 0 ? sum / n : std::nan("");
  }
  double pixels = 0.0;
  for (const ImageMetrics& m : frames) pixels += double(m.reflector_pixels);
  out.reflector_pixels = frames.empty() ? 0 : size_t(std::lround(pixels / double(frames.size())));
  return out;
}

namespace {

// The mean of each figure over the frames that have the region (pixels and sse: over all frames,
// 0 where it is absent, so that the means still add up across regions).
RegionMetrics meanRegion(const std::vector<const RegionMetrics*>& present, size_t frames) {
  RegionMetrics out;
  double pixels = 0.0, sse = 0.0, psnr = 0.0, ssim = 0.0, flip = 0.0;
  int figures = 0;
  for (const RegionMetrics* r : present) {
    pixels += double(r->pixels);
    sse += r->sse;
    if (r->pixels == 0) continue;
    psnr += r->psnr, ssim += r->ssim, flip += r->flip, ++figures;
  }
  out.pixels = size_t(std::lround(pixels / double(std::max<size_t>(frames, 1))));
  out.sse = sse / double(std::max<size_t>(frames, 1));
  out.psnr = figures ? psnr / figures : std::nan("");
  out.ssim = figures ? ssim / figures : std::nan("");
  out.flip = figures ? flip / figures : std::nan("");
  return out;
}

std::map<std::string, RegionMetrics> meanRegionMap(
    const std::vector<RegionSet>& frames, std::map<std::string, RegionMetrics> RegionSet::*member) {
  std::map<std::string, std::vector<const RegionMetrics*>> by_name;
  for (const RegionSet& f : frames)
    for (const auto& [name, r] : f.*member) by_name[name].push_back(&r);
  std::map<std::string, RegionMetrics> out;
  for (const auto& [name, present] : by_name) out[name] = meanRegion(present, frames.size());
  return out;
}

}  // namespace

RegionSet meanRegions(const std::vector<RegionSet>& frames) {
  RegionSet out;
  out.reflectors = meanRegionMap(frames, &RegionSet::reflectors);
  out.causes = meanRegionMap(frames, &RegionSet::causes);
  out.diffuse_objects = meanRegionMap(frames, &RegionSet::diffuse_objects);
  out.layers = meanRegionMap(frames, &RegionSet::layers);
  std::vector<const RegionMetrics*> mixed;
  for (const RegionSet& f : frames) {
    out.has_causes = out.has_causes || f.has_causes;
    mixed.push_back(&f.mixed);
  }
  out.mixed = meanRegion(mixed, frames.size());
  return out;
}

ImageMetrics worstMetrics(const std::vector<ImageMetrics>& frames) {
  ImageMetrics out;
  for (const Figure& f : kFigures) {
    double worst = std::nan("");
    for (const ImageMetrics& m : frames) {
      double v = m.*f.field;
      if (std::isnan(v)) continue;
      if (std::isnan(worst) || (f.higher_is_better ? v < worst : v > worst)) worst = v;
    }
    out.*f.field = worst;
  }
  out.reflector_pixels = 0;
  for (const ImageMetrics& m : frames)
    out.reflector_pixels = std::max(out.reflector_pixels, m.reflector_pixels);
  return out;
}

namespace report_html {

namespace {

const Column kPathColumns[] = {
    {"PSNR reflector mean", "reflector pixels, mean over the frames; higher is better", "{:.2f}",
     true, [](const MethodReport& m) { return m.metrics.psnr_reflector; }},
    {"PSNR reflector worst", "reflector pixels, the lowest frame; higher is better", "{:.2f}", true,
     [](const MethodReport& m) { return m.worst.psnr_reflector; }},
    {"SSIM reflector mean", "reflector pixels, mean over the frames; higher is better", "{:.4f}",
     true, [](const MethodReport& m) { return m.metrics.ssim_reflector; }},
    {"SSIM reflector worst", "reflector pixels, the lowest frame; higher is better", "{:.4f}", true,
     [](const MethodReport& m) { return m.worst.ssim_reflector; }},
    {"FLIP reflector mean", "mean over reflector pixels and frames; lower is better", "{:.4f}",
     false, [](const MethodReport& m) { return m.metrics.flip_reflector; }},
    {"FLIP reflector worst", "the highest frame; lower is better", "{:.4f}", false,
     [](const MethodReport& m) { return m.worst.flip_reflector; }},
    {"PSNR mean", "all pixels, mean over the frames; higher is better", "{:.2f}", true,
     [](const MethodReport& m) { return m.metrics.psnr; }},
    {"temporal error", "mean frame-to-frame change of the error on reflector pixels (display "
     "values, 0..1); the reference's own change is above the table; lower is better",
     "{:.4f}", false, [](const MethodReport& m) { return m.temporal_error; }},
    {"ms", "mean frame after the first; lower is better", "{:.2f}", false,
     [](const MethodReport& m) { return m.ms; }},
    kFirstFrameColumn,
};

// The reflector PSNR of every method frame by frame (all pixels in the cell's tooltip).
std::string frameTable(const CompareReport& r) {
  std::string head = "<th>frame</th><th>time s</th>";
  for (const MethodReport& m : r.methods)
    if (!isReference(r, m)) head += fmt::format("<th>{}</th>", escape(m.name));
  std::string rows;
  for (size_t f = 0; f < r.path.times.size(); ++f) {
    std::string row = fmt::format("<tr><td>{}</td><td>{:.3f}</td>", f, r.path.times[f]);
    for (const MethodReport& m : r.methods) {
      if (isReference(r, m)) continue;
      const ImageMetrics* x = f < m.frame_metrics.size() ? &m.frame_metrics[f] : nullptr;
      row += x ? fmt::format("<td title=\"all pixels {}\">{}</td>", cell(x->psnr, "{:.2f}"),
                             cell(x->psnr_reflector, "{:.2f}"))
               : "<td>&ndash;</td>";
    }
    rows += row + "</tr>\n";
  }
  return fmt::format("<table><thead><tr>{}</tr></thead><tbody>\n{}</tbody></table>", head, rows);
}

const ShownFrame* shownFrame(const MethodReport& m, int frame) {
  for (const ShownFrame& s : m.shown)
    if (s.frame == frame) return &s;
  return nullptr;
}

std::string frameCaption(const CompareReport& r, int frame) {
  float t = frame < int(r.path.times.size()) ? r.path.times[size_t(frame)] : 0.0f;
  return fmt::format("frame {}, t = {:.2f} s", frame, t);
}

// The reference's shown frames side by side.
std::string referenceSection(const CompareReport& r, const MethodReport& ref) {
  std::string figures;
  for (const ShownFrame& s : ref.shown)
    figures += fmt::format(
        "<figure><img src=\"{}\" alt=\"reference, {}\"><figcaption>{}</figcaption></figure>\n",
        escape(s.image), frameCaption(r, s.frame), frameCaption(r, s.frame));
  return fmt::format(
      "<section id=reference><h2>Reference: {}</h2><p class=d>{}</p><div class=maps>\n{}</div>"
      "</section>\n",
      escape(ref.name), escape(ref.description), figures);
}

// One method: per shown frame its image, |error| map and FLIP map with that frame's figures.
std::string methodFrames(const CompareReport& r, const MethodReport& m, const MethodReport* ref) {
  std::string rows;
  for (const ShownFrame& s : m.shown) {
    const ImageMetrics& x = m.frame_metrics[size_t(s.frame)];
    const ShownFrame* rs = ref ? shownFrame(*ref, s.frame) : nullptr;
    std::string ref_attr = rs ? fmt::format(" data-ref=\"{}\"", escape(rs->image)) : "";
    rows += fmt::format(
        "<div class=maps>\n"
        "<figure><img src=\"{img}\" alt=\"{name}: {frame}\"{ref_attr}><figcaption><b>{frame}"
        "</b>{hint}<br>{ms} ms</figcaption></figure>\n"
        "<figure><img src=\"{err}\" alt=\"{name}: absolute error, {frame}\"><figcaption>"
        "<b>|error|</b> vs {refname}{errbar}PSNR {psnr} dB, reflector {psnr_r} dB<br>SSIM {ssim}, "
        "reflector {ssim_r}</figcaption></figure>\n"
        "<figure><img src=\"{flip}\" alt=\"{name}: FLIP map, {frame}\"><figcaption><b>FLIP</b> vs "
        "{refname}{flipbar}mean {flip_all}, reflector {flip_r}</figcaption></figure>\n"
        "</div>\n",
        fmt::arg("img", escape(s.image)), fmt::arg("name", escape(m.name)),
        fmt::arg("frame", frameCaption(r, s.frame)), fmt::arg("ref_attr", ref_attr),
        fmt::arg("hint",
                 rs ? " <small>(hold a mouse button on it to see the reference)</small>" : ""),
        fmt::arg("ms", cell(m.frame_ms[size_t(s.frame)], "{:.2f}")),
        fmt::arg("err", escape(s.error_image)), fmt::arg("refname", escape(r.reference)),
        fmt::arg("errbar", colourBar("0", fmt::format("{:g}", r.heatmap_max / 2),
                                     fmt::format("&ge; {:g}", r.heatmap_max))),
        fmt::arg("psnr", cell(x.psnr, "{:.2f}")),
        fmt::arg("psnr_r", cell(x.psnr_reflector, "{:.2f}")),
        fmt::arg("ssim", cell(x.ssim, "{:.4f}")),
        fmt::arg("ssim_r", cell(x.ssim_reflector, "{:.4f}")),
        fmt::arg("flip", escape(s.flip_image)), fmt::arg("flipbar", colourBar("0", "0.5", "1")),
        fmt::arg("flip_all", cell(x.flip, "{:.4f}")),
        fmt::arg("flip_r", cell(x.flip_reflector, "{:.4f}")));
  }
  return fmt::format(
      "<section class=method id=\"m-{0}\"><h3>{0}</h3><p class=d>{1}</p>\n<p>Reflector PSNR "
      "mean {2} dB, worst {3} dB; {4}</p>\n{5}</section>\n",
      escape(m.name), escape(m.description), cell(m.metrics.psnr_reflector, "{:.2f}"),
      cell(m.worst.psnr_reflector, "{:.2f}"),
      m.note.empty() ? fmt::format("order {}", m.order_rendered) : escape(m.note), rows);
}

}  // namespace

void addPathJson(const CompareReport& r, nlohmann::json& j) {
  nlohmann::json path;
  path["camera"] = r.path.camera;
  path["frames"] = r.path.times.size();
  path["times"] = r.path.times;
  path["reference_change_reflector"] = number(r.path.reference_change);
  nlohmann::json change = nlohmann::json::array();
  for (double v : r.path.frame_reference_change) change.push_back(number(v));
  path["per_frame_reference_change_reflector"] = change;
  j["path"] = path;
  for (const MethodReport& m : r.methods) {
    nlohmann::json& e = j["methods"][m.name];
    nlohmann::json worst = metricsFields(m.worst);
    worst.erase("reflector_pixels");
    e["worst"] = worst;
    nlohmann::json per_frame;
    for (const char* key :
         {"psnr", "psnr_reflector", "ssim", "ssim_reflector", "flip", "flip_reflector"})
      per_frame[key] = nlohmann::json::array();
    per_frame["reflector_pixels"] = nlohmann::json::array();
    for (const ImageMetrics& x : m.frame_metrics) {
      nlohmann::json fields = metricsFields(x);
      for (auto it = fields.begin(); it != fields.end(); ++it) per_frame[it.key()].push_back(*it);
    }
    per_frame["ms"] = nlohmann::json::array();
    for (double ms : m.frame_ms) per_frame["ms"].push_back(number(ms));
    e["temporal_error_reflector"] = number(m.temporal_error);
    per_frame["temporal_error_reflector"] = nlohmann::json::array();
    for (double v : m.frame_temporal_error) per_frame["temporal_error_reflector"].push_back(number(v));
    // The methods' counters per frame (e.g. zexel's exposed_fraction); `stats` holds their means.
    nlohmann::json stats = nlohmann::json::object();
    for (const auto& frame : m.frame_stats)
      for (const auto& [key, value] : frame) stats[key].push_back(number(value));
    per_frame["stats"] = stats;
    e["per_frame"] = per_frame;
    nlohmann::json images = nlohmann::json::array();
    for (const ShownFrame& s : m.shown)
      images.push_back({{"frame", s.frame},
                        {"image", s.image},
                        {"error_image", s.error_image},
                        {"flip_image", s.flip_image}});
    e["images"] = images;
  }
}

std::string pathReportHtml(const CompareReport& r) {
  const MethodReport* ref = referenceOf(r);
  std::string figures;
  for (const MethodReport& m : r.methods)
    if (&m != ref) figures += methodFrames(r, m, ref);
  const float first = r.path.times.front(), last = r.path.times.back();
  PageParts parts;
  parts.title = r.scene + ", camera path";
  parts.setup = fmt::format(
      R"(Camera path <b>{}</b>: {} frames from t = {:.2f} s to {:.2f} s. Each method
renders the frames in order and keeps its state from one frame to the next, as in an animation.
The reference's reflections change by {} a frame on its reflector pixels (the mean absolute
change of display values): the scale of the methods' temporal errors.
)",
      escape(r.path.camera), r.path.times.size(), first, last,
      cell(r.path.reference_change, "{:.4f}"));
  parts.kept = " Images are kept for the first, middle and last frame.";
  parts.reference_section = ref ? referenceSection(r, *ref) : "";
  parts.metrics =
      metricsSection(
          r, "Metrics over the path", kPathColumns,
          R"(Mean: over the frames (frames without reflector pixels left out of the reflector
figures). Worst: the lowest PSNR or SSIM, the highest FLIP of any frame. &uarr; higher is better,
&darr; lower is better; green: the best of each column among the methods other than the
reference. Click a column header to sort.)") +
      fmt::format("\n<section id=frames><h2>Reflector PSNR per frame (dB)</h2>\n{}\n</section>",
                  frameTable(r));
  parts.figures = figures;
  return reportPage(r, parts);
}

}  // namespace report_html

}  // namespace mirage
