// The comparison report of `mirage compare`: DIR/index.html (the reference, then every method's
// image, absolute-error map and FLIP map with their metrics, and a sortable metrics table) and
// DIR/metrics.json, both written atomically. The HTML is self-contained: it loads nothing but
// the report's own PNGs.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/math.h"
#include "eval/metrics.h"

namespace mirage {

struct MethodReport {
  std::string name;
  std::string description;
  ImageMetrics metrics;
  double ms = 0.0;         // one steady frame (after the first frame's captures/builds)
  double first_ms = 0.0;   // the first frame, captures and builds included
  int order_rendered = 0;  // reflection order the method produced
  std::string note;        // e.g. "order 1 only"
  std::map<std::string, double> stats;
  std::string image;  // file names relative to the report directory
  std::string error_image;
  std::string flip_image;
};

struct CompareReport {
  std::string scene;
  std::string scene_description;
  ivec2 size{0};
  int order = 0;
  std::string reference = "raytrace";
  std::string device;  // GL renderer
  std::string cpu;     // CPU model
  size_t triangles = 0;
  float heatmap_max = 0.0f;  // error value drawn as the brightest heat-map colour
  float flip_ppd = 0.0f;     // pixels per degree the FLIP figures assume
  std::string tonemap;
  std::vector<MethodReport> methods;
};

// JSON value for a metric: numbers, null for NaN (no such pixels) and for +inf (identical).
std::string metricsJson(const CompareReport& report);
// The first method named `report.reference` is shown as the reference; the others are ranked.
std::string reportHtml(const CompareReport& report);
void writeCompareReport(const std::string& directory, const CompareReport& report);

}  // namespace mirage
