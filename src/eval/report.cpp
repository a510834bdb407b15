#include "eval/report.h"

#include <cmath>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "eval/heatmap.h"
#include "eval/report_html.h"

namespace mirage {

namespace report_html {

nlohmann::json number(double v) {
  if (!std::isfinite(v)) return nullptr;
  return v;
}

std::string cell(double v, const char* format) {
  if (std::isnan(v)) return "&ndash;";
  if (std::isinf(v)) return "&infin;";
  return fmt::format(fmt::runtime(format), v);
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

// The magma map as a CSS gradient: magma() is linear between these nine stops, so the bar shows
// exactly the colours of the PNGs.
std::string magmaGradient() {
  std::string stops;
  for (int i = 0; i <= 8; ++i) {
    vec3 c = magma(float(i) / 8.0f) * 255.0f;
    stops += fmt::format(",rgb({},{},{}) {}%", int(std::lround(c.x)), int(std::lround(c.y)),
                         int(std::lround(c.z)), i * 100 / 8);
  }
  return "linear-gradient(to right" + stops + ")";
}

}  // namespace

std::string colourBar(const std::string& low, const std::string& mid, const std::string& high) {
  return fmt::format(
      "<div class=bar></div><div class=ticks><span>{}</span><span>{}</span><span>{}</span></div>",
      low, mid, high);
}

std::string pageStyle() {
  return R"(<style>
body{font-family:system-ui,sans-serif;margin:1.5em;background:#fafafa;color:#222;
     max-width:1600px}
h1{margin:0 0 .2em} h2{margin:1.4em 0 .4em;border-bottom:1px solid #ddd} h3{margin:.2em 0}
.d{margin:.2em 0;color:#555;max-width:960px} small{color:#666}
table{border-collapse:collapse;margin:.6em 0}
td,th{border:1px solid #ccc;padding:.3em .6em;text-align:right}
th{background:#eee;cursor:pointer;user-select:none}
th[data-dir=asc]::after{content:" \25B4"} th[data-dir=desc]::after{content:" \25BE"}
td:first-child,th:first-child,td:last-child,th:last-child{text-align:left}
tr.ref td{background:#f0f0f0;color:#555}
td.best{background:#d4f4d4;font-weight:bold}
.maps{display:grid;grid-template-columns:repeat(3,minmax(0,1fr));gap:.8em;margin:.4em 0 1.2em}
figure{margin:0} img{max-width:100%;height:auto;border:1px solid #ccc;display:block}
figcaption{font-size:.9em;margin-top:.3em;line-height:1.4}
.bar{height:12px;max-width:320px;margin-top:.3em;border:1px solid #ccc;background:)" +
         magmaGradient() + R"(}
.ticks{display:flex;justify-content:space-between;max-width:322px;font-size:.8em;color:#555;
        margin-bottom:.2em}
.method{border-top:1px solid #ddd;padding-top:.6em} ul{max-width:960px}
</style>)";
}

// Sorting (click a header; the reference row stays on top) and flipping (hold a mouse button on
// a method's image to see the reference in its place, the comparison FLIP models).
const char* const kScript = R"(
document.querySelectorAll('#metrics th').forEach((th, col) => {
  th.addEventListener('click', () => {
    const body = th.closest('table').tBodies[0];
    const rows = [...body.rows].filter(r => !r.classList.contains('ref'));
    const down = th.dataset.dir !== 'asc';
    th.closest('tr').querySelectorAll('th').forEach(h => delete h.dataset.dir);
    th.dataset.dir = down ? 'asc' : 'desc';
    const key = r => r.cells[col].dataset.v ?? '';
    const text = th.dataset.type === 'text';
    rows.sort((a, b) => {
      const x = key(a), y = key(b);
      if (text) return down ? x.localeCompare(y) : y.localeCompare(x);
      if (x === '' || y === '') return (x === '') - (y === '');
      return down ? Number(x) - Number(y) : Number(y) - Number(x);
    });
    rows.forEach(r => body.appendChild(r));
  });
});
document.querySelectorAll('img[data-ref]').forEach(img => {
  const own = img.getAttribute('src');
  img.addEventListener('pointerdown', e => { e.preventDefault(); img.src = img.dataset.ref; });
  ['pointerup', 'pointerleave', 'pointercancel'].forEach(t =>
    img.addEventListener(t, () => { img.src = own; }));
});
)";

nlohmann::json metricsFields(const ImageMetrics& m) {
  nlohmann::json e;
  e["psnr"] = number(m.psnr);
  e["psnr_reflector"] = number(m.psnr_reflector);
  e["ssim"] = number(m.ssim);
  e["ssim_reflector"] = number(m.ssim_reflector);
  e["flip"] = number(m.flip);
  e["flip_reflector"] = number(m.flip_reflector);
  e["reflector_pixels"] = m.reflector_pixels;
  return e;
}

// How to read the figures, for both kinds of report; `ms_note` says what the ms column holds.
std::string readingSection(const CompareReport& r) {
  const char* ms_note =
      r.path.times.empty()
          ? "<li><b>ms</b>: one steady frame, after a first frame that does the captures and "
            "builds; use <code>mirage bench</code> for timing.</li>"
          : "<li><b>ms</b>: the mean frame of the path after the first, which does the captures "
            "and builds (<b>first frame ms</b>); use <code>mirage bench</code> for timing.</li>";
  return fmt::format(
      R"(<section id=reading><h2>How to read this report</h2><ul>
<li><b>Reflector</b> columns are computed over the pixels the reference's reflector-ID buffer marks:
where the reflections are. The whole-image figures are dominated by the direct view, which every
method draws alike, so compare methods by the reflector columns.</li>
<li><b>PSNR</b> (dB, peak 1, mean squared RGB error): &infin; means identical. <b>SSIM</b> (luma,
11&times;11 Gaussian window): 1 means identical.</li>
<li><b>FLIP</b> (LDR-FLIP, Andersson et al. 2020) estimates the difference a viewer notices when
flipping between a method's image and the reference, per pixel from 0 (none) to 1; it weighs colour
differences by what the eye resolves at the viewing distance and adds a penalty for edges and points
that differ. Viewing conditions: {ppd:.1f} pixels per degree (a 0.7 m wide 3840-pixel screen seen
from 0.7 m). The table gives its mean.</li>
<li><b>Maps</b>, coloured with magma on fixed scales, the same for every method:
|error| is the mean absolute RGB difference (black 0, pale yellow &ge; {hmax:g});
FLIP goes from 0 (black) to 1 (pale yellow). Bright areas are where to look.</li>
{ms_note}
</ul></section>
)",
      fmt::arg("ppd", r.flip_ppd), fmt::arg("hmax", r.heatmap_max), fmt::arg("ms_note", ms_note));
}

bool isReference(const CompareReport& r, const MethodReport& m) {
  return m.name == r.reference;
}

const MethodReport* referenceOf(const CompareReport& r) {
  for (const MethodReport& m : r.methods)
    if (isReference(r, m)) return &m;
  return nullptr;
}

// The best value of a column among the methods other than the reference (NaN if none): the
// reference against itself is trivially perfect, so ranking it would say nothing.
double bestOf(const CompareReport& r, const Column& c) {
  double best = std::nan("");
  for (const MethodReport& m : r.methods) {
    double v = c.get(m);
    if (isReference(r, m) || std::isnan(v)) continue;
    if (std::isnan(best) || (c.higher_is_better ? v > best : v < best)) best = v;
  }
  return best;
}

std::string tableRows(const CompareReport& r, std::span<const Column> columns) {
  std::vector<double> best;
  for (const Column& c : columns) best.push_back(bestOf(r, c));
  std::string rows;
  for (const MethodReport& m : r.methods) {
    bool ref = isReference(r, m);
    std::string row = fmt::format("<tr{}><td data-v=\"{}\"><a href=\"#{}\">{}</a>{}</td>",
                                  ref ? " class=ref" : "", escape(m.name),
                                  ref ? "reference" : "m-" + escape(m.name), escape(m.name),
                                  ref ? " <small>(reference)</small>" : "");
    for (size_t i = 0; i < columns.size(); ++i) {
      double v = columns[i].get(m);
      bool is_best = !ref && !std::isnan(v) && v == best[i];
      std::string key = std::isnan(v) ? "" : std::isinf(v) ? "Infinity" : fmt::format("{}", v);
      row += fmt::format("<td data-v=\"{}\"{}>{}</td>", key, is_best ? " class=best" : "",
                         cell(v, columns[i].format));
    }
    rows += row + fmt::format("<td data-v=\"{0}\">{0}</td><td data-v=\"{1}\">{1}</td></tr>\n",
                              m.order_rendered, escape(m.note));
  }
  return rows;
}

std::string tableHeader(std::span<const Column> columns) {
  std::string h = "<th data-type=text title=\"click to sort\">method</th>";
  for (const Column& c : columns)
    h += fmt::format("<th title=\"{}; click to sort\">{} {}</th>", c.tip, c.title,
                     c.higher_is_better ? "&uarr;" : "&darr;");
  return h +
         "<th title=\"reflection order rendered; click to sort\">order</th><th "
         "data-type=text>note</th>";
}

}  // namespace report_html

namespace {

using namespace report_html;

const Column kColumns[] = {
    {"PSNR dB", "all pixels; higher is better", "{:.2f}", true,
     [](const MethodReport& m) { return m.metrics.psnr; }},
    {"PSNR reflector", "reflector pixels; higher is better", "{:.2f}", true,
     [](const MethodReport& m) { return m.metrics.psnr_reflector; }},
    {"SSIM", "all pixels; higher is better", "{:.4f}", true,
     [](const MethodReport& m) { return m.metrics.ssim; }},
    {"SSIM reflector", "reflector pixels; higher is better", "{:.4f}", true,
     [](const MethodReport& m) { return m.metrics.ssim_reflector; }},
    {"FLIP", "mean over all pixels; lower is better", "{:.4f}", false,
     [](const MethodReport& m) { return m.metrics.flip; }},
    {"FLIP reflector", "mean over reflector pixels; lower is better", "{:.4f}", false,
     [](const MethodReport& m) { return m.metrics.flip_reflector; }},
    {"ms", "one steady frame; lower is better", "{:.2f}", false,
     [](const MethodReport& m) { return m.ms; }},
    kFirstFrameColumn,
};

std::string methodFigures(const CompareReport& r, const MethodReport& m, const MethodReport* ref) {
  const ImageMetrics& x = m.metrics;
  std::string ref_attr = ref ? fmt::format(" data-ref=\"{}\"", escape(ref->image)) : "";
  return fmt::format(
      "<section class=method id=\"m-{name}\"><h3>{name}</h3><p class=d>{desc}</p>\n"
      "<div class=maps>\n"
      "<figure><img src=\"{img}\" alt=\"{name}: image\"{ref_attr}><figcaption><b>image</b>{hint}"
      "<br>{ms} ms per frame, first frame {first} ms; {order}</figcaption></figure>\n"
      "<figure><img src=\"{err}\" alt=\"{name}: absolute error\"><figcaption><b>|error|</b> vs "
      "{refname}{errbar}PSNR {psnr} dB, reflector {psnr_r} dB<br>SSIM {ssim}, reflector {ssim_r}"
      "</figcaption></figure>\n"
      "<figure><img src=\"{flip}\" alt=\"{name}: FLIP map\"><figcaption><b>FLIP</b> vs "
      "{refname}{flipbar}mean {flip_all}, reflector {flip_r}</figcaption></figure>\n"
      "</div></section>\n",
      fmt::arg("name", escape(m.name)), fmt::arg("desc", escape(m.description)),
      fmt::arg("img", escape(m.image)), fmt::arg("ref_attr", ref_attr),
      fmt::arg("hint",
               ref ? " <small>(hold a mouse button on it to see the reference)</small>" : ""),
      fmt::arg("ms", cell(m.ms, "{:.2f}")), fmt::arg("first", cell(m.first_ms, "{:.2f}")),
      fmt::arg("order",
               m.note.empty() ? fmt::format("order {}", m.order_rendered) : escape(m.note)),
      fmt::arg("err", escape(m.error_image)), fmt::arg("refname", escape(r.reference)),
      fmt::arg("errbar", colourBar("0", fmt::format("{:g}", r.heatmap_max / 2),
                                   fmt::format("&ge; {:g}", r.heatmap_max))),
      fmt::arg("psnr", cell(x.psnr, "{:.2f}")),
      fmt::arg("psnr_r", cell(x.psnr_reflector, "{:.2f}")),
      fmt::arg("ssim", cell(x.ssim, "{:.4f}")),
      fmt::arg("ssim_r", cell(x.ssim_reflector, "{:.4f}")), fmt::arg("flip", escape(m.flip_image)),
      fmt::arg("flipbar", colourBar("0", "0.5", "1")), fmt::arg("flip_all", cell(x.flip, "{:.4f}")),
      fmt::arg("flip_r", cell(x.flip_reflector, "{:.4f}")));
}

}  // namespace

std::string metricsJson(const CompareReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["size"] = {r.size.x, r.size.y};
  j["order"] = r.order;
  j["reference"] = referenceJson(r);
  j["ssaa"] = r.reference_info.ssaa;
  j["timing"] = r.timing;
  j["device"] = r.device;
  j["cpu"] = r.cpu;
  j["triangles"] = r.triangles;
  j["tonemap"] = r.tonemap;
  j["flip_pixels_per_degree"] = number(r.flip_ppd);
  j["object_layers"] = r.object_layers;
  nlohmann::json methods = nlohmann::json::object();
  for (const MethodReport& m : r.methods) {
    nlohmann::json e = metricsFields(m.metrics);
    e.update(regionsJson(m.regions));
    e["ms"] = number(m.ms);
    e["first_frame_ms"] = number(m.first_ms);
    e["order_rendered"] = m.order_rendered;
    if (!m.note.empty()) e["note"] = m.note;
    if (!m.fallback.empty()) e["fallback"] = m.fallback;
    nlohmann::json stats = nlohmann::json::object();
    for (const auto& [k, v] : m.stats) stats[k] = number(v);
    e["stats"] = stats;
    methods[m.name] = e;
  }
  j["methods"] = methods;
  if (!r.path.times.empty()) addPathJson(r, j);
  return j.dump(2) + "\n";
}

std::string reportHtml(const CompareReport& r) {
  if (!r.path.times.empty()) return pathReportHtml(r);
  const MethodReport* ref = referenceOf(r);
  std::string reference_section, figures;
  if (ref)
    reference_section = fmt::format(
        "<section id=reference><h2>Reference: {0}</h2><p class=d>{1}</p>"
        "<figure><img src=\"{2}\" alt=\"reference image ({0})\"><figcaption>{3} ms per frame"
        "</figcaption></figure></section>\n",
        escape(ref->name), escape(ref->description), escape(ref->image), cell(ref->ms, "{:.1f}"));
  for (const MethodReport& m : r.methods)
    if (&m != ref) figures += methodFigures(r, m, ref);
  PageParts parts;
  parts.title = r.scene;
  parts.reference_section = reference_section;
  parts.metrics = metricsSection(
      r, "Metrics", kColumns,
      R"(&uarr; higher is better, &darr; lower is better. Green: the best value of each column
among the methods other than the reference. Click a column header to sort (the reference stays
on top).)");
  parts.figures = figures;
  return reportPage(r, parts);
}

namespace report_html {

std::string metricsSection(const CompareReport& r, const std::string& title,
                           std::span<const Column> columns, const std::string& note) {
  return fmt::format(R"(<section id=metrics><h2>{}</h2>
<table><thead><tr>{}</tr></thead><tbody>
{}</tbody></table>
<p class=d>{}</p>
</section>)",
                     title, tableHeader(columns), tableRows(r, columns), note);
}

std::string reportPage(const CompareReport& r, const PageParts& parts) {
  return fmt::format(
      R"(<!doctype html>
<html lang=en><head><meta charset=utf-8><meta name=viewport content="width=device-width">
<title>mirage compare: {title}</title>
{style}</head><body>
<h1>{scene}</h1>
<p class=d>{desc}</p>
<p>{w}&times;{h} pixels, {tris} triangles, reflection order K = {order}, reference: <b>{reference}</b>.
{setup}Device: {device}; CPU: {cpu}. Images after the display transform ({tonemap}); all metrics on those
values.{kept}</p>
{sampling}
{reference_section}{metrics}
{regions}{reading}<section id=methods><h2>Methods against the reference</h2>
{figures}</section>
<script>{script}</script>
</body></html>
)",
      fmt::arg("title", escape(parts.title)), fmt::arg("scene", escape(r.scene)),
      fmt::arg("desc", escape(r.scene_description)), fmt::arg("style", pageStyle()),
      fmt::arg("w", r.size.x), fmt::arg("h", r.size.y), fmt::arg("tris", r.triangles),
      fmt::arg("order", r.order), fmt::arg("reference", escape(r.reference)),
      fmt::arg("setup", parts.setup), fmt::arg("device", escape(r.device)),
      fmt::arg("cpu", escape(r.cpu)), fmt::arg("tonemap", escape(r.tonemap)),
      fmt::arg("kept", parts.kept), fmt::arg("sampling", samplingNote(r)),
      fmt::arg("reference_section", parts.reference_section), fmt::arg("metrics", parts.metrics),
      fmt::arg("regions", regionSections(r)), fmt::arg("reading", readingSection(r)),
      fmt::arg("figures", parts.figures), fmt::arg("script", kScript));
}

}  // namespace report_html

void writeCompareReport(const std::string& directory, const CompareReport& report) {
  std::filesystem::path dir(directory);
  writeFileAtomic((dir / "metrics.json").string(), metricsJson(report));
  writeFileAtomic((dir / "index.html").string(), reportHtml(report));
}

}  // namespace mirage
