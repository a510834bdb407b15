// The comparison report of `mirage compare`: DIR/index.html (the reference, then every method's
// image, absolute-error map and FLIP map with their metrics, and a sortable metrics table) and
// DIR/metrics.json, both written atomically; for one view or for the frames of a camera path.
// The HTML is self-contained: it loads nothing but the report's own PNGs.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/math.h"
#include "eval/metrics.h"
#include "eval/regions.h"

namespace mirage {

// A frame of a camera path whose images the report keeps (the first, middle and last).
struct ShownFrame {
  int frame = 0;
  std::string image, error_image, flip_image;
};

// A method's error split into regions of the frame: by reflector, and by cause (eval/causes.h).
struct RegionSet {
  std::map<std::string, RegionMetrics> reflectors;       // by the reflector instance's name
  bool has_causes = false;                               // false: no ray tracer classified them
  std::map<std::string, RegionMetrics> causes;           // by cause name; pixels add up to all
  std::map<std::string, RegionMetrics> diffuse_objects;  // the `diffuse` cause by object name
  // By layer of the reflected scene (scene/layers.h): `environment` (the sky and the environment
  // instances' diffuse pixels), `object` (the object instances'), `reflectors` (the causes self,
  // reflector and beyond_order).
  std::map<std::string, RegionMetrics> layers;
  RegionMetrics mixed;  // reflector pixels whose sub-pixels met different things
};
// The mean over frames of each region's figures (frames without the region left out).
RegionSet meanRegions(const std::vector<RegionSet>& frames);

struct MethodReport {
  std::string name;
  std::string description;
  ImageMetrics metrics;
  double ms = 0.0;         // one steady frame (after the first frame's captures/builds)
  double first_ms = 0.0;   // the first frame, captures and builds included
  int order_rendered = 0;  // reflection order the method produced
  std::string note;        // e.g. "order 1 only"
  std::string fallback;    // why envmap drew in its place (the driver refused it), or empty
  std::map<std::string, double> stats;
  std::string image;  // file names relative to the report directory
  std::string error_image;
  std::string flip_image;
  RegionSet regions;

  // Camera-path reports (`--path-frames`): one entry per frame. `metrics` then holds the means
  // over the frames, `worst` the worst frame's value of each figure, `ms` the mean of the frames
  // after the first and `first_ms` the first, `stats` the means of the frames' counters;
  // `shown` replaces the three image names.
  std::vector<ImageMetrics> frame_metrics;
  std::vector<double> frame_ms;
  std::vector<std::map<std::string, double>> frame_stats;
  std::vector<RegionSet> frame_regions;
  ImageMetrics worst;
  std::vector<ShownFrame> shown;
  // Its temporal error on reflector pixels (eval/temporal.h): the mean over the frames after the
  // first, and each frame's (NaN for the first).
  double temporal_error = 0.0;
  std::vector<double> frame_temporal_error;
};

// The frames of a camera path a report covers; no times: one view.
struct PathInfo {
  std::string camera;        // the scene camera whose path was sampled
  std::vector<float> times;  // scene time of each frame, seconds
  // The reference's own frame-to-frame change on its reflector pixels (eval/temporal.h: the
  // reference against black): the scale a method's temporal error is read against.
  double reference_change = 0.0;
  std::vector<double> frame_reference_change;
};

// How the reference was sampled, and how far that is from converged (`--reference-check`).
struct ReferenceInfo {
  int ssaa = 1;           // sub-pixels per side, the same for every method (--ssaa)
  bool checked = false;   // a converged image was rendered
  int converged_spp = 0;  // its stratified samples per pixel (--reference-spp)
  double noise_floor_psnr = 0.0, noise_floor_psnr_reflector = 0.0;  // reference vs converged
};

struct CompareReport {
  std::string scene;
  std::string scene_description;
  ivec2 size{0};
  int order = 0;
  std::string reference = "raytrace";
  ReferenceInfo reference_info;
  std::string timing;       // how the ms columns were measured (native runs under --ssaa)
  std::string cause_image;  // the cause classification drawn (eval/causes.h), or empty
  std::vector<std::string> reflector_names;  // in reflector-id order
  // Each diffuse instance's layer (scene/layers.h) by its name, as diffuse_objects names it.
  std::map<std::string, std::string> object_layers;
  std::string device;                        // GL renderer
  std::string cpu;                           // CPU model
  size_t triangles = 0;
  float heatmap_max = 0.0f;  // error value drawn as the brightest heat-map colour
  float flip_ppd = 0.0f;     // pixels per degree the FLIP figures assume
  std::string tonemap;
  PathInfo path;
  std::vector<MethodReport> methods;
};

// The means (over frames with a value: NaN frames, without reflector pixels, are left out) and
// the worst values (lowest PSNR and SSIM, highest FLIP) of per-frame metrics.
ImageMetrics meanMetrics(const std::vector<ImageMetrics>& frames);
ImageMetrics worstMetrics(const std::vector<ImageMetrics>& frames);

// JSON value for a metric: numbers, null for NaN (no such pixels) and for +inf (identical).
// Path reports add "path" and per method "worst", "per_frame" (arrays) and "images".
std::string metricsJson(const CompareReport& report);
// The first method named `report.reference` is shown as the reference; the others are ranked.
// Path reports show the means and worst frames, a per-frame table and the shown frames' images.
std::string reportHtml(const CompareReport& report);
void writeCompareReport(const std::string& directory, const CompareReport& report);

}  // namespace mirage
