#include "eval/report.h"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"

namespace mirage {

namespace {

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
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string metricsJson(const CompareReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["size"] = {r.size.x, r.size.y};
  j["order"] = r.order;
  j["reference"] = r.reference;
  j["device"] = r.device;
  j["cpu"] = r.cpu;
  j["triangles"] = r.triangles;
  j["tonemap"] = r.tonemap;
  nlohmann::json methods = nlohmann::json::object();
  for (const MethodReport& m : r.methods) {
    nlohmann::json e;
    e["psnr"] = number(m.metrics.psnr);
    e["psnr_reflector"] = number(m.metrics.psnr_reflector);
    e["ssim"] = number(m.metrics.ssim);
    e["ssim_reflector"] = number(m.metrics.ssim_reflector);
    e["ms"] = number(m.ms);
    e["first_frame_ms"] = number(m.first_ms);
    e["reflector_pixels"] = m.metrics.reflector_pixels;
    e["order_rendered"] = m.order_rendered;
    if (!m.note.empty()) e["note"] = m.note;
    nlohmann::json stats = nlohmann::json::object();
    for (const auto& [k, v] : m.stats) stats[k] = number(v);
    e["stats"] = stats;
    methods[m.name] = e;
  }
  j["methods"] = methods;
  return j.dump(2) + "\n";
}

std::string reportHtml(const CompareReport& r) {
  std::string rows, figures;
  for (const MethodReport& m : r.methods) {
    rows += fmt::format(
        "<tr><td><b>{}</b></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td></tr>\n",
        escape(m.name), cell(m.metrics.psnr, "{:.2f}"), cell(m.metrics.psnr_reflector, "{:.2f}"),
        cell(m.metrics.ssim, "{:.4f}"), cell(m.metrics.ssim_reflector, "{:.4f}"),
        cell(m.ms, "{:.2f}"), cell(m.first_ms, "{:.2f}"), m.order_rendered, escape(m.note));
    figures += fmt::format(
        "<div class=m><h3>{}</h3><p class=d>{}</p>"
        "<figure><img src=\"{}\" alt=\"{} image\"><figcaption>image</figcaption></figure>"
        "<figure><img src=\"{}\" alt=\"{} error\"><figcaption>|error| vs {}</figcaption></figure>"
        "</div>\n",
        escape(m.name), escape(m.description), escape(m.image), escape(m.name),
        escape(m.error_image), escape(m.name), escape(r.reference));
  }
  return fmt::format(R"(<!doctype html>
<html lang=en><head><meta charset=utf-8><title>mirage compare: {scene}</title>
<style>
body{{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}}
table{{border-collapse:collapse;margin:1em 0}} td,th{{border:1px solid #ccc;padding:.3em .6em;text-align:right}}
td:first-child,th:first-child{{text-align:left}} .m{{display:inline-block;vertical-align:top;margin:0 1em 1em 0}}
figure{{display:inline-block;margin:0 .5em 0 0}} img{{max-width:480px;image-rendering:pixelated;border:1px solid #ccc}}
.d{{margin:.2em 0;color:#555;max-width:960px}} .bar{{width:300px;height:14px;background:linear-gradient(to right,#000004,#3b0f70,#8c2981,#de4968,#fe9f6d,#fcfdbf)}}
</style></head><body>
<h1>{scene}</h1>
<p>{desc}</p>
<p>{w}&times;{h} pixels, {tris} triangles, reflection order K = {order}, reference: <b>{reference}</b>.
Device: {device}; CPU: {cpu}. Images after the display transform ({tonemap}); metrics on those values.</p>
<table><tr><th>method</th><th>PSNR dB</th><th>PSNR reflector</th><th>SSIM</th><th>SSIM reflector</th>
<th>ms</th><th>first frame ms</th><th>order</th><th>note</th></tr>
{rows}</table>
<p>PSNR/SSIM "reflector" are computed over the pixels the reference's reflector-ID buffer marks as
reflector; &infin; means identical. ms: one frame after the first (which includes captures and
builds). Error maps: mean absolute RGB difference, 0 <span class=bar style="display:inline-block"></span> {hmax} and above.</p>
{figures}
</body></html>
)",
                     fmt::arg("scene", escape(r.scene)), fmt::arg("desc", escape(r.scene_description)),
                     fmt::arg("w", r.size.x), fmt::arg("h", r.size.y), fmt::arg("tris", r.triangles),
                     fmt::arg("order", r.order), fmt::arg("reference", escape(r.reference)),
                     fmt::arg("device", escape(r.device)), fmt::arg("cpu", escape(r.cpu)),
                     fmt::arg("tonemap", escape(r.tonemap)), fmt::arg("rows", rows),
                     fmt::arg("hmax", r.heatmap_max), fmt::arg("figures", figures));
}

void writeCompareReport(const std::string& directory, const CompareReport& report) {
  std::filesystem::path dir(directory);
  writeFileAtomic((dir / "metrics.json").string(), metricsJson(report));
  writeFileAtomic((dir / "index.html").string(), reportHtml(report));
}

}  // namespace mirage
