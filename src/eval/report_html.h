// What the two kinds of compare report (one view: report.cpp; a camera path: report_path.cpp)
// share: value formatting, the page's style and script, the reading notes. Internal to eval/.
#pragma once

#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "eval/report.h"

namespace mirage::report_html {

// A metric as JSON: null for NaN (no such pixels) and infinities (identical).
nlohmann::json number(double v);
// A metric in a table cell: "&ndash;" for NaN, "&infin;" for +inf.
std::string cell(double v, const char* format);
std::string escape(const std::string& s);
// The magma colour bar under a map, with three tick labels.
std::string colourBar(const std::string& low, const std::string& mid, const std::string& high);
// The <style> element of both pages.
std::string pageStyle();
// Sorting the #metrics table by a header click; showing the reference while an image is pressed.
extern const char* const kScript;
// The "How to read this report" section.
std::string readingSection(const CompareReport& r);
// The JSON of one set of metrics (psnr, psnr_reflector, ssim, ..., reflector_pixels).
nlohmann::json metricsFields(const ImageMetrics& m);

// A metrics-table column: how to read it from a method, print it, and which way is better.
struct Column {
  const char* title;
  const char* tip;
  const char* format;
  bool higher_is_better;
  double (*get)(const MethodReport&);
};

// The first frame's time (captures and builds), a column of both pages' tables.
inline constexpr Column kFirstFrameColumn{"first frame ms",
                                          "captures and builds included; lower is better", "{:.2f}",
                                          false, [](const MethodReport& m) { return m.first_ms; }};

bool isReference(const CompareReport& r, const MethodReport& m);
// The first method that is the reference, or null.
const MethodReport* referenceOf(const CompareReport& r);
// The best value of a column among the methods other than the reference (NaN if none).
double bestOf(const CompareReport& r, const Column& c);
// The #metrics table: a header cell per column (plus method, order, note), a row per method with
// the best value of each column marked.
std::string tableHeader(std::span<const Column> columns);
std::string tableRows(const CompareReport& r, std::span<const Column> columns);

// The regions of a method (metrics.json: reflectors, causes, diffuse_objects, mixed), the
// reference's object (method, ssaa, noise floor), the sampling and noise-floor paragraphs, and the
// per-reflector and per-cause sections of the page (report_regions.cpp).
nlohmann::json regionsJson(const RegionSet& regions);
nlohmann::json referenceJson(const CompareReport& r);
std::string samplingNote(const CompareReport& r);
std::string regionSections(const CompareReport& r);

// The #metrics section: its title, the table of `columns` and a note under it.
std::string metricsSection(const CompareReport& r, const std::string& title,
                           std::span<const Column> columns, const std::string& note);
// A compare page: the header every page has (the scene; size, triangles, order and reference,
// then `setup`, what was run; the machine and the display transform, then `kept`, which images
// are kept; the sampling note), then `reference_section`, the `metrics` sections, the regions,
// the reading notes and the methods' `figures`. `title` follows "mirage compare: ".
struct PageParts {
  std::string title, setup, kept, reference_section, metrics, figures;
};
std::string reportPage(const CompareReport& r, const PageParts& parts);

// The camera-path additions: "path" at the top, "worst", "per_frame" and "images" per method.
void addPathJson(const CompareReport& r, nlohmann::json& j);
std::string pathReportHtml(const CompareReport& r);

}  // namespace mirage::report_html
