// Simplified rotated depth maps on the CPU (the impostor paper, §4.1-4.2): sampling a depth map
// along the rows of n rotated domains without building rotated maps, simplifying every row to at
// most m points (the paper's greedy refinement, or greedy knots with a least-squares fit of
// their depths), the multithreaded builder, and the relative z error of the result. The layout
// and the ray-row intersection are in srdm_shared.h.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace mirage {

// A square depth map: normalised depth d in [0, 1] (GL window depth of a perspective camera with
// planes near < far), row-major, y up; d >= 1 is background.
struct DepthMap {
  int size = 0;
  float near = 0.1f, far = 10.0f;
  std::vector<float> depth;

  float at(int x, int y) const { return depth[size_t(y) * size_t(size) + size_t(x)]; }
  static bool isForeground(float d) { return d < 1.0f; }
  // Eye-space distance along the camera axis of normalised depth d.
  float eyeDepth(float d) const { return near * far / (far - d * (far - near)); }
};

enum class SrdmSimplifier {
  kGreedy,  // the paper: split the worst segment at its worst sample until m points
  kFit,     // the greedy knots, then each span's depths fitted by weighted least squares
};
SrdmSimplifier parseSrdmSimplifier(const std::string& name);  // throws InputError
const char* srdmSimplifierName(SrdmSimplifier s);

struct SrdmSettings {
  int domains = 60;  // n: rotated domains theta_i = pi i / n
  int points = 8;    // m: points per simplified row (>= 2)
  SrdmSimplifier simplifier = SrdmSimplifier::kGreedy;
};

// One row of a rotated domain, sampled from the depth map at its nearest texels: samples at
// s_k = (k + 0.5) spacing, spacing = E / ceil(E) <= 1 texel, for the k whose points lie over
// the foreground's bounding box `box` (the rest of the row is background); d = 1 where the row
// meets background.
struct RowSamples {
  float spacing = 1.0f;
  std::vector<float> s, d;
};
// The bounding box of the foreground texels: x0, y0, x1, y1 (x1, y1 exclusive).
ivec4 foregroundBox(const DepthMap& map);
void sampleRow(const DepthMap& map, const ivec4& box, int domain, int domains, int row,
               RowSamples& out);

// A simplified row: points (s, d) with s increasing; span_start marks a point whose incoming
// segment is a gap. At most m points; spans beyond m / 2 are dropped, the shortest first
// (counted in `dropped`), so that rays pass through thin slivers rather than hit false bridges.
struct RowPolyline {
  std::vector<vec2> points;
  std::vector<bool> span_start;
  int dropped = 0;  // foreground samples of the spans that did not fit
};
void simplifyRow(const DepthMap& map, const RowSamples& row, int m, SrdmSimplifier simplifier,
                 RowPolyline& out);

// The polyline's depth at s, or -1 where s is in a gap or outside every span.
float evaluateRow(const RowPolyline& row, float s);

struct Srdm {
  int size = 0, domains = 0, points = 0;
  std::vector<vec4> texels;  // domains x size rows x pairs(), two points per texel (see shared)
  int dropped_samples = 0;

  int pairs() const { return (points + 1) / 2; }
  vec4 pair(int domain, int row, int pair) const {
    return texels[(size_t(domain) * size_t(size) + size_t(row)) * size_t(pairs()) + size_t(pair)];
  }
  size_t bytes() const { return texels.size() * sizeof(vec4); }
};

// Row `row` of domain `domain`, unpacked (padding included, as span starts).
RowPolyline decodeRow(const Srdm& srdm, int domain, int row);

// Throws InputError unless 1 <= n <= 1024 and 2 <= m <= min(w, 256) (both builders check).
void checkSrdmSettings(int size, const SrdmSettings& settings);

// Builds all n * w rows in parallel (TBB). Throws InputError for settings out of range.
Srdm buildSrdm(const DepthMap& map, const SrdmSettings& settings);

// The shader's ray-SRDM searches (srdm_intersect_shared.h).
enum class SrdmSearch {
  kOneRow,               // the row through the projected ray's midpoint (the paper)
  kTwoRowsHit,           // then the row through that row's hit (--srdm-second hit)
  kTwoRowsInterpolated,  // the two nearest domains' rows, interpolated (--srdm-second interpolate)
  kHitInterpolated,      // those two through the first row's hit (--srdm-second hit-interpolate)
};

// The shader's ray-SRDM intersection (srdm_intersect_shared.h), run on the CPU: the first crossing
// of the ray whose clipped projection runs from `from` to `to` in (x, y, d) texel space, as the
// fraction of the way, or -1.
float intersectSrdm(const Srdm& srdm, vec3 from, vec3 to, SrdmSearch search = SrdmSearch::kOneRow);

// The relative z error |z' - z| / z of the simplified rows at every foreground sample of every
// row of every domain (z the eye depth; z' that of the polyline at the sample), the paper's
// "average relative z error over all depth map texels and all SRDMs"; samples of dropped spans
// are counted apart.
struct SrdmError {
  double mean = 0.0, max = 0.0;
  long samples = 0, dropped = 0;
};
SrdmError measureSrdmError(const DepthMap& map, const Srdm& srdm);

}  // namespace mirage
