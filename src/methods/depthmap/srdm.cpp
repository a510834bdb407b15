#include "methods/depthmap/srdm.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "methods/depthmap/srdm_build_shared.h"
#include "methods/depthmap/srdm_shared.h"

namespace mirage {

namespace sh = shading;

SrdmSimplifier parseSrdmSimplifier(const std::string& name) {
  if (name == "greedy") return SrdmSimplifier::kGreedy;
  if (name == "fit") return SrdmSimplifier::kFit;
  throwInput("--srdm-simplify: unknown simplifier '{}' (allowed: greedy, fit)", name);
}

const char* srdmSimplifierName(SrdmSimplifier s) {
  return s == SrdmSimplifier::kGreedy ? "greedy" : "fit";
}

ivec4 foregroundBox(const DepthMap& map) {
  ivec4 box(map.size, map.size, 0, 0);  // x0, y0, x1, y1 (exclusive); empty when x0 >= x1
  for (int y = 0; y < map.size; ++y)
    for (int x = 0; x < map.size; ++x)
      if (DepthMap::isForeground(map.at(x, y)))
        box = ivec4(glm::min(ivec2(box), ivec2(x, y)),
                    glm::max(ivec2(box.z, box.w), ivec2(x + 1, y + 1)));
  return box;
}

void sampleRow(const DepthMap& map, const ivec4& box, int domain, int domains, int row,
               RowSamples& out) {
  const float w = float(map.size);
  const float theta = sh::srdm_theta(domain, domains);
  const float extent = sh::srdm_extent(theta, w);
  const int count = sh::srdm_sample_count(extent);
  out.spacing = extent / float(count);
  out.s.clear();
  out.d.clear();
  // The shared row arithmetic (srdm_build_shared.h), as the GPU builder runs it.
  const vec2 a(std::cos(theta), std::sin(theta));
  const vec2 start = sh::srdm_row_start(a, extent, row, w);
  // Only the part of the row over the foreground's bounding box: the rest is background.
  const ivec2 range = sh::srdm_row_range(start, a, box, extent, out.spacing, count);
  for (int k = range.x; k <= range.y; ++k) {
    const float s = sh::srdm_sample_s(k, out.spacing);
    const ivec2 p = sh::srdm_sample_texel(start, a, s);
    const bool inside = p.x >= 0 && p.y >= 0 && p.x < map.size && p.y < map.size;
    out.s.push_back(s);
    out.d.push_back(inside ? std::min(map.at(p.x, p.y), 1.0f) : 1.0f);
  }
}

namespace {

// Relative eye-depth error of depth d_approx where the truth is d: with z = n f / (f - d (f - n))
// and k = (f - n) / f, |z' - z| / z = k |d' - d| / (1 - k d').
struct RelativeZ {
  float k;
  explicit RelativeZ(const DepthMap& map) : k((map.far - map.near) / map.far) {}
  float operator()(float d_approx, float d) const { return sh::srdm_relative_z(k, d_approx, d); }
};

struct Span {
  int first, last;  // sample indices, inclusive
};

// The row's foreground spans; beyond `keep`, the shortest are dropped (ties: the later).
std::vector<Span> findSpans(const RowSamples& row, int keep, int& dropped) {
  std::vector<Span> spans;
  const int count = int(row.d.size());
  for (int k = 0; k < count;) {
    if (!DepthMap::isForeground(row.d[size_t(k)])) {
      ++k;
      continue;
    }
    int last = k;
    while (last + 1 < count && DepthMap::isForeground(row.d[size_t(last + 1)])) ++last;
    spans.push_back({k, last});
    k = last + 1;
  }
  dropped = 0;
  if (int(spans.size()) <= keep) return spans;
  std::stable_sort(spans.begin(), spans.end(), [](const Span& x, const Span& y) {
    return x.last - x.first > y.last - y.first;
  });
  for (size_t i = size_t(keep); i < spans.size(); ++i)
    dropped += spans[i].last - spans[i].first + 1;
  spans.resize(size_t(keep));
  std::sort(spans.begin(), spans.end(),
            [](const Span& x, const Span& y) { return x.first < y.first; });
  return spans;
}

// A knot of the polyline under construction: its position, depth, the sample it sits on (the
// span's end samples for the two ends, which sit half a sample outside) and the next knot.
struct Knot {
  float s, d;
  int sample;
  int next;
};

struct Segment {
  float error;
  int left, worst;  // the knot starting the segment; the sample of largest error
  // The queue's order (shared with the GPU builder): ties go to the earlier worst sample.
  bool operator<(const Segment& o) const {
    return sh::srdm_segment_above(o.error, o.worst, error, worst);
  }
};

Segment worstOfSegment(const std::vector<Knot>& knots, int left, const RowSamples& row,
                       const RelativeZ& rel) {
  const Knot& a = knots[size_t(left)];
  const Knot& b = knots[size_t(a.next)];
  Segment seg{0.0f, left, -1};
  const float inv = sh::srdm_segment_inverse(a.s, b.s);
  for (int k = a.sample; k <= b.sample; ++k) {
    const float approx = sh::srdm_segment_depth(a.s, a.d, b.d, inv, row.s[size_t(k)]);
    const float e = rel(approx, row.d[size_t(k)]);
    if (e > seg.error) {
      seg.error = e;
      seg.worst = k;
    }
  }
  return seg;
}

// Weighted least squares of the knots' depths with their positions fixed, one span: hat basis
// functions, a tridiagonal system (Thomas). The weights make squared depth error approximate
// squared relative z error; a tiny pull towards the current depths keeps knots with no sample
// between them determined.
void fitSpan(std::vector<Knot>& knots, int first, const RowSamples& row, const RelativeZ& rel) {
  std::vector<int> ids;
  for (int i = first; i >= 0; i = knots[size_t(i)].next) {
    ids.push_back(i);
    if (knots[size_t(i)].next >= 0 && knots[size_t(knots[size_t(i)].next)].sample < 0) break;
  }
  const size_t n = ids.size();
  if (n < 2) return;
  std::vector<double> diag(n, 0.0), off(n, 0.0), rhs(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i) {
    const Knot& a = knots[size_t(ids[i])];
    const Knot& b = knots[size_t(ids[i + 1])];
    const int k_lo = i == 0 ? a.sample : a.sample + 1;
    for (int k = k_lo; k <= b.sample; ++k) {
      const double s = row.s[size_t(k)], d = row.d[size_t(k)];
      const double u = std::clamp((s - a.s) / (b.s - a.s), 0.0, 1.0);
      const double wt = std::pow(rel.k / std::max(1.0 - rel.k * d, 1e-6), 2.0);
      diag[i] += wt * (1 - u) * (1 - u);
      diag[i + 1] += wt * u * u;
      off[i] += wt * u * (1 - u);
      rhs[i] += wt * (1 - u) * d;
      rhs[i + 1] += wt * u * d;
    }
  }
  const double ridge = 1e-9 * (*std::max_element(diag.begin(), diag.end()) + 1e-30);
  for (size_t i = 0; i < n; ++i) {
    diag[i] += ridge;
    rhs[i] += ridge * knots[size_t(ids[i])].d;
  }
  // Thomas algorithm: sub- and super-diagonals are both off[].
  std::vector<double> c(n, 0.0), x(n, 0.0);
  double denom = diag[0];
  c[0] = off[0] / denom;
  x[0] = rhs[0] / denom;
  for (size_t i = 1; i < n; ++i) {
    denom = diag[i] - off[i - 1] * c[i - 1];
    c[i] = off[i] / denom;
    x[i] = (rhs[i] - off[i - 1] * x[i - 1]) / denom;
  }
  for (size_t i = n - 1; i-- > 0;) x[i] -= c[i] * x[i + 1];
  for (size_t i = 0; i < n; ++i)
    knots[size_t(ids[i])].d = float(std::clamp(x[i], 0.0, double(std::nextafter(1.0f, 0.0f))));
}

}  // namespace

void simplifyRow(const DepthMap& map, const RowSamples& row, int m, SrdmSimplifier simplifier,
                 RowPolyline& out) {
  const RelativeZ rel(map);
  std::vector<Span> spans = findSpans(row, m / 2, out.dropped);
  // Knots in a linked list; a sentinel (sample -1) ends each span's chain.
  std::vector<Knot> knots;
  std::vector<int> heads;
  std::priority_queue<Segment> queue;
  const float half = 0.5f * row.spacing;
  for (const Span& sp : spans) {
    const int a = int(knots.size());
    heads.push_back(a);
    knots.push_back({row.s[size_t(sp.first)] - half, row.d[size_t(sp.first)], sp.first, a + 1});
    knots.push_back({row.s[size_t(sp.last)] + half, row.d[size_t(sp.last)], sp.last, a + 2});
    knots.push_back({0.0f, 1.0f, -1, -1});  // sentinel
    queue.push(worstOfSegment(knots, a, row, rel));
  }
  // The paper's refinement: split the worst segment at its worst sample until m points.
  int count = 2 * int(spans.size());
  while (count < m && !queue.empty() && queue.top().error > 0.0f) {
    const Segment seg = queue.top();
    queue.pop();
    const int mid = int(knots.size());
    const int right = knots[size_t(seg.left)].next;
    knots.push_back({row.s[size_t(seg.worst)], row.d[size_t(seg.worst)], seg.worst, right});
    knots[size_t(seg.left)].next = mid;
    queue.push(worstOfSegment(knots, seg.left, row, rel));
    queue.push(worstOfSegment(knots, mid, row, rel));
    ++count;
  }
  if (simplifier == SrdmSimplifier::kFit)
    for (int head : heads) fitSpan(knots, head, row, rel);

  out.points.clear();
  out.span_start.clear();
  for (int head : heads) {
    for (int i = head; knots[size_t(i)].sample >= 0; i = knots[size_t(i)].next) {
      out.points.emplace_back(knots[size_t(i)].s, knots[size_t(i)].d);
      out.span_start.push_back(i == head);
    }
  }
}

float evaluateRow(const RowPolyline& row, float s) {
  for (size_t i = 1; i < row.points.size(); ++i) {
    if (row.span_start[i]) continue;
    const vec2 a = row.points[i - 1], b = row.points[i];
    if (s >= a.x && s <= b.x && b.x > a.x) return a.y + (b.y - a.y) * (s - a.x) / (b.x - a.x);
  }
  return -1.0f;
}

namespace {

// Packs a row's points into its texels; pads with the last point (or the row's start) marked as
// a span start, so that padding segments are gaps.
void packRow(const RowPolyline& row, float first_s, int m, vec4* texels) {
  auto encoded = [&](int k) -> vec2 {
    if (k < int(row.points.size())) {
      const vec2 p = row.points[size_t(k)];
      return row.span_start[size_t(k)] ? vec2(-p.x, p.y) : p;
    }
    const vec2 last = row.points.empty() ? vec2(first_s, 1.0f) : row.points.back();
    return vec2(-last.x, last.y);
  };
  const int pairs = (m + 1) / 2;
  for (int p = 0; p < pairs; ++p) {
    const vec2 x = encoded(2 * p), y = encoded(2 * p + 1);
    texels[p] = vec4(x.x, x.y, y.x, y.y);
  }
}

}  // namespace

RowPolyline decodeRow(const Srdm& srdm, int domain, int row) {
  RowPolyline out;
  for (int p = 0; p < srdm.pairs(); ++p) {
    const vec4 t = srdm.pair(domain, row, p);
    for (vec2 q : {vec2(t.x, t.y), vec2(t.z, t.w)}) {
      if (int(out.points.size()) == srdm.points) break;
      out.points.emplace_back(std::abs(q.x), q.y);
      out.span_start.push_back(q.x < 0.0f);
    }
  }
  return out;
}

void checkSrdmSettings(int size, const SrdmSettings& settings) {
  if (settings.domains < 1 || settings.domains > 1024)
    throwInput("--srdm-n {} is out of range (allowed: 1..1024)", settings.domains);
  if (settings.points < 2 || settings.points > std::min(size, 256))
    throwInput(
        "--srdm-m {} is out of range (allowed: 2..{}, at most the depth map's size "
        "--depthmap-size)",
        settings.points, std::min(size, 256));
}

Srdm buildSrdm(const DepthMap& map, const SrdmSettings& settings) {
  checkSrdmSettings(map.size, settings);
  Srdm srdm;
  srdm.size = map.size;
  srdm.domains = settings.domains;
  srdm.points = settings.points;
  srdm.texels.resize(size_t(srdm.domains) * size_t(srdm.size) * size_t(srdm.pairs()));
  tbb::combinable<int> dropped(0);
  const int rows = srdm.domains * srdm.size;
  const ivec4 box = foregroundBox(map);
  tbb::parallel_for(tbb::blocked_range<int>(0, rows, 64), [&](const tbb::blocked_range<int>& r) {
    RowSamples samples;
    RowPolyline poly;
    for (int index = r.begin(); index != r.end(); ++index) {
      const int domain = index / srdm.size, row = index % srdm.size;
      sampleRow(map, box, domain, srdm.domains, row, samples);
      simplifyRow(map, samples, srdm.points, settings.simplifier, poly);
      dropped.local() += poly.dropped;
      packRow(poly, 0.5f, srdm.points, &srdm.texels[size_t(index) * size_t(srdm.pairs())]);
    }
  });
  srdm.dropped_samples = dropped.combine(std::plus<int>());
  return srdm;
}

}  // namespace mirage

// The C++ side of the shared intersection: rows read from the Srdm being searched.
namespace mirage::shading {
namespace {
thread_local const Srdm* g_searched = nullptr;
}
inline vec4 srdm_point_pair(int domain, int row, int pair) {
  return g_searched->pair(domain, row, pair);
}
}  // namespace mirage::shading

#include "methods/depthmap/srdm_intersect_shared.h"

namespace mirage {

float intersectSrdm(const Srdm& srdm, vec3 from, vec3 to, SrdmSearch search) {
  sh::g_searched = &srdm;
  const int n = srdm.domains, w = srdm.size, m = srdm.points;
  const bool hit_first =
      search == SrdmSearch::kTwoRowsHit || search == SrdmSearch::kHitInterpolated;
  const bool interpolate =
      search == SrdmSearch::kTwoRowsInterpolated || search == SrdmSearch::kHitInterpolated;
  return sh::srdm_search(from, to, n, w, m, hit_first, interpolate);
}

SrdmError measureSrdmError(const DepthMap& map, const Srdm& srdm) {
  struct Sum {
    double total = 0.0, max = 0.0;
    long samples = 0, dropped = 0;
  };
  tbb::combinable<Sum> sums;
  const RelativeZ rel(map);
  const ivec4 box = foregroundBox(map);
  tbb::parallel_for(0, srdm.domains * srdm.size, [&](int index) {
    const int domain = index / srdm.size, row = index % srdm.size;
    RowSamples samples;
    sampleRow(map, box, domain, srdm.domains, row, samples);
    const RowPolyline poly = decodeRow(srdm, domain, row);
    Sum& sum = sums.local();
    for (size_t k = 0; k < samples.s.size(); ++k) {
      if (!DepthMap::isForeground(samples.d[k])) continue;
      const float approx = evaluateRow(poly, samples.s[k]);
      if (approx < 0.0f) {
        ++sum.dropped;
        continue;
      }
      const double e = rel(approx, samples.d[k]);
      sum.total += e;
      sum.max = std::max(sum.max, e);
      ++sum.samples;
    }
  });
  SrdmError out;
  double total = 0.0;
  sums.combine_each([&](const Sum& s) {
    total += s.total;
    out.max = std::max(out.max, s.max);
    out.samples += s.samples;
    out.dropped += s.dropped;
  });
  out.mean = out.samples > 0 ? total / double(out.samples) : 0.0;
  return out;
}

}  // namespace mirage
