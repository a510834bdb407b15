#include "app/advise.h"

#include <charconv>
#include <cmath>

#include <spdlog/spdlog.h>

#include "app/advise_choice.h"
#include "app/timing_summary.h"
#include "core/error.h"
#include "core/progress.h"
#include "eval/metrics.h"
#include "gpu/frame_timer.h"
#include "methods/assignment.h"
#include "methods/frame.h"

namespace mirage::app {

namespace {

// Each method's main parameters: the grid advise tries besides the defaults.
struct GridPoint {
  const char* method;
  std::map<std::string, std::string> params;
};
const std::vector<GridPoint>& gridPoints() {
  static const std::vector<GridPoint> points = {
      {"envmap", {{"envmap-size", "64"}}},        {"envmap-box", {{"envmap-size", "64"}}},
      {"billboard", {{"billboard-size", "128"}}}, {"depthmap", {{"srdm-m", "16"}}},
      {"depthmap", {{"depthmap-size", "128"}}},   {"planar", {{"order", "1"}}},
      {"zexel", {{"zexel-size", "256"}}},
  };
  return points;
}

// The frames of one assignment timed at the output size: the median frame and each entry's.
struct Timed {
  double total_ms = 0.0;
  std::vector<double> part_ms;
};

class Advisor {
 public:
  Advisor(const Scene& scene, const AdviseSetup& setup)
      : scene_(scene),
        setup_(setup),
        quality_(scene, setup.size * setup.ssaa),
        timing_(scene, setup.size),
        reflectors_(scene.reflectorInstances()) {}

  Advice run() {
    if (reflectors_.empty()) throwInput("scene '{}' has no reflector to advise on", scene_name());
    const size_t r_count = reflectors_.size(), c_count = setup_.candidates.size();
    const size_t views = setup_.views.size();
    const size_t timed_frames = size_t(setup_.frames) * views + 2;
    Progress progress("advise",
                      (2 * c_count + 2) * views + (c_count * (r_count + 1) + 3) * timed_frames);
    progress_ = &progress;
    Advice a;
    for (int i : reflectors_) a.reflectors.push_back(scene_.instances[size_t(i)].name);
    references();
    a.pixels = pixels_;
    a.measured.assign(r_count, {});
    for (const Candidate& cand : setup_.candidates) attempt(a, cand, [&] { measureQuality(a, cand); });
    a.none_ms = time("none", {}, "").total_ms;
    const Timed base = time("mixed", {}, "*=none");
    a.base_ms = base.total_ms - base.part_ms.at(0);
    for (size_t c = 0; c < a.candidates.size();) {
      const Candidate cand = a.candidates[c];
      if (attempt(a, cand, [&] { measureCost(a, c); }))
        ++c;
      else
        drop(a, c);
    }
    a.budget_ms = setup_.budget.ms(a.none_ms);
    choose(a);
    const std::string text = assignText(a.rules);
    a.measured_sse = 0.0;
    for (double e : reflectorErrors("mixed", {}, text)) a.measured_sse += e;
    a.measured_ms = time("mixed", {}, text).total_ms;
    return a;
  }

 private:
  const std::string& scene_name() const { return scene_.name; }

  // Runs one candidate's `measure`; where the method fails (a RuntimeError: an error of its own,
  // or a fallback to another method), records why in a.failed and says so. Whether it worked.
  template <typename Measure>
  bool attempt(Advice& a, const Candidate& cand, Measure&& measure) {
    try {
      measure();
      return true;
    } catch (const RuntimeError& e) {
      a.failed.push_back({cand.label, e.what()});
      spdlog::warn("advise: candidate '{}' failed, left out: {}", cand.label, e.what());
      if (a.failed.size() == setup_.candidates.size())
        throwRuntime("advise: every candidate failed on '{}' (the last: {})", scene_name(),
                     e.what());
      return false;
    }
  }

  // The candidate's error on each reflector: each as a composite draws it (an entry of its own:
  // a method drawn beside others may show what it sees otherwise, as planar its curved
  // reflectors), then the method alone, the single-method frame. Appends it to a.candidates.
  void measureQuality(Advice& a, const Candidate& cand) {
    const size_t r_count = reflectors_.size();
    std::string each;
    for (const std::string& name : a.reflectors)
      each += (each.empty() ? "" : ";") + name + "=" + cand.label;
    const std::vector<double> alone = reflectorErrors(cand.method, cand.params, "");
    const std::vector<double> sse = r_count > 1 ? reflectorErrors("mixed", {}, each) : alone;
    double sum = 0.0;
    for (size_t r = 0; r < r_count; ++r) {
      a.measured[r].push_back({sse[r], 0.0});
      sum += alone[r];
    }
    a.candidates.push_back(cand);
    a.single_sse.push_back(sum);
  }

  // Candidate c's costs: its single-method frame, each reflector's part, its entry overhead.
  void measureCost(Advice& a, size_t c) {
    const Candidate& cand = a.candidates[c];
    const size_t r_count = reflectors_.size();
    const double single = time(cand.method, cand.params, "").total_ms;
    std::vector<double> part(r_count);
    double parts = 0.0, least = 1e300;
    for (size_t r = 0; r < r_count; ++r) {
      const std::string text = a.reflectors[r] + "=" + cand.label + ";*=none";
      part[r] = time("mixed", {}, text).part_ms.at(0);
      parts += part[r];
      least = std::min(least, part[r]);
    }
    for (size_t r = 0; r < r_count; ++r) a.measured[r][c].part_ms = part[r];
    a.single_ms.push_back(single);
    // The entry's overhead: what the parts timed one reflector at a time add up to beyond the
    // candidate drawing all of them in one entry (its frame less the rest of a frame).
    const double all = single - a.base_ms;
    a.fixed_ms.push_back(r_count > 1 ? std::clamp((parts - all) / double(r_count - 1), 0.0, least)
                                     : 0.0);
  }

  // Removes candidate c, whose costs failed, from the lists its quality filled.
  static void drop(Advice& a, size_t c) {
    a.candidates.erase(a.candidates.begin() + std::ptrdiff_t(c));
    a.single_sse.erase(a.single_sse.begin() + std::ptrdiff_t(c));
    for (auto& row : a.measured) row.erase(row.begin() + std::ptrdiff_t(c));
  }

  void choose(Advice& a) const {
    // Each reflector's cost beyond its candidate's entry overhead, paid once per entry.
    std::vector<std::vector<Option>> options(a.reflectors.size());
    for (size_t r = 0; r < options.size(); ++r)
      for (size_t c = 0; c < a.candidates.size(); ++c)
        options[r].push_back({a.measured[r][c].part_ms - a.fixed_ms[c], a.measured[r][c].sse});
    std::optional<Choice> choice =
        chooseWithFixed(options, a.fixed_ms, a.budget_ms - a.base_ms, kMaxAdviseEntries);
    a.fits = choice.has_value();
    if (!choice) choice = cheapest(options, a.fixed_ms);
    a.chosen = choice->picked;
    a.predicted_ms = a.base_ms + choice->cost_ms;
    a.predicted_sse = choice->sse;
    // One entry per candidate chosen, naming its reflectors.
    for (size_t c = 0; c < a.candidates.size(); ++c) {
      ReflectionRule rule{{}, a.candidates[c].method, a.candidates[c].params, "advise"};
      for (size_t r = 0; r < a.chosen.size(); ++r)
        if (a.chosen[r] == int(c)) rule.reflectors.push_back(a.reflectors[r]);
      if (!rule.reflectors.empty()) a.rules.push_back(std::move(rule));
    }
  }

  // The ray tracer's frames of every view: the reference, and each reflector's pixels in it
  // (a mask per view and reflector, made once for every candidate's frames).
  void references() {
    pixels_.assign(reflectors_.size(), 0);
    for (const CalibrationView& v : setup_.views) {
      RenderedFrame f = renderQuality("raytrace", {}, "", v);
      std::vector<ReflectorMask> masks;
      for (size_t r = 0; r < reflectors_.size(); ++r) {
        IdImage mask = f.ids;
        for (uint32_t& id : mask.pixels()) id = id == uint32_t(r + 1) ? 1u : 0u;
        const size_t n = countNonZero(mask);
        pixels_[r] += n;
        masks.push_back({std::move(mask), n});
      }
      masks_.push_back(std::move(masks));
      reference_.push_back(toDisplay(f.color, setup_.display));
    }
  }

  // What a method is made with: the candidate's parameters over the given ones, `mixed`'s
  // assignment, and the frame settings at `pixel_scale` with the candidate's order.
  struct Made {
    std::map<std::string, std::string> params;
    FrameSettings settings;
  };
  Made made(const std::string& method, std::map<std::string, std::string> params,
            const std::string& assign, int pixel_scale) const {
    for (const auto& [k, value] : setup_.params) params.try_emplace(k, value);
    if (!assign.empty()) params[kAssignParam] = assign;
    FrameSettings settings = setup_.settings;
    settings.pixel_scale = pixel_scale;
    if (auto it = params.find("order"); it != params.end() && method != "mixed") {
      settings.order = std::stoi(it->second);
      params.erase(it);
    }
    return {std::move(params), settings};
  }

  // A method that fell back to another shows the other's frame under its name: a failure here.
  static void refuseFallback(const Method& m, const std::string& method) {
    if (!m.fallbackReason().empty())
      throwRuntime("'{}' fell back to 'envmap': {}", method, m.fallbackReason());
  }

  RenderedFrame renderQuality(const std::string& method,
                              const std::map<std::string, std::string>& params,
                              const std::string& assign, const CalibrationView& v) {
    const auto [given, settings] = made(method, params, assign, setup_.ssaa);
    auto m = quality_.createMethod(method, given, settings);
    quality_.render(*m, View(v.camera, quality_.size()), v.time, settings);
    refuseFallback(*m, method);
    progress_->advance();
    return downsample(quality_.read(), setup_.ssaa);
  }

  // Each reflector's summed squared error over the views (its pixels in the reference).
  std::vector<double> reflectorErrors(const std::string& method,
                                      const std::map<std::string, std::string>& params,
                                      const std::string& assign) {
    std::vector<double> sse(reflectors_.size(), 0.0);
    for (size_t v = 0; v < setup_.views.size(); ++v) {
      const Image shown =
          toDisplay(renderQuality(method, params, assign, setup_.views[v]).color, setup_.display);
      for (size_t r = 0; r < reflectors_.size(); ++r) {
        const ReflectorMask& m = masks_[v][r];
        if (m.pixels > 0)
          sse[r] += meanSquaredError(shown, reference_[v], &m.mask) * double(m.pixels);
      }
    }
    return sse;
  }

  // Times one assignment (or one method alone): two untimed frames, then `frames` rounds over
  // the views, timed by the wall clock around glFinish.
  Timed time(const std::string& method, const std::map<std::string, std::string>& params,
             const std::string& assign) {
    const auto [given, settings] = made(method, params, assign, 1);  // at the output size
    auto m = timing_.createMethod(method, given, settings);
    const CalibrationView& first = setup_.views.front();
    for (int i = 0; i < 2; ++i) {
      timing_.render(*m, View(first.camera, setup_.size), first.time, settings);
      refuseFallback(*m, method);
      progress_->advance();
    }
    std::vector<double> total;
    std::vector<std::vector<double>> parts;
    for (int f = 0; f < setup_.frames; ++f)
      for (const CalibrationView& v : setup_.views) {
        gpu::FrameTimer timer(gpu::Clock::kWall);
        timing_.render(*m, View(v.camera, setup_.size), v.time, settings, &timer);
        total.push_back(timer.takeResults().front().total_ms);
        const std::vector<Method::PartTime> p = m->partTimes();
        parts.resize(p.size());
        for (size_t k = 0; k < p.size(); ++k) parts[k].push_back(p[k].ms);
        progress_->advance();
      }
    Timed out{summarize(total).median, {}};
    for (const auto& list : parts) out.part_ms.push_back(summarize(list).median);
    return out;
  }

  const Scene& scene_;
  const AdviseSetup& setup_;
  FrameRenderer quality_, timing_;
  std::vector<int> reflectors_;
  struct ReflectorMask {
    IdImage mask;  // 1 where the reference shows the reflector
    size_t pixels = 0;
  };
  std::vector<Image> reference_;
  std::vector<std::vector<ReflectorMask>> masks_;  // [view][reflector]
  std::vector<size_t> pixels_;
  Progress* progress_ = nullptr;
};

}  // namespace

Budget parseBudget(const std::string& b) {
  const bool relative = !b.empty() && (b.back() == 'x' || b.back() == 'X');
  const std::string number = relative ? b.substr(0, b.size() - 1) : b;
  double v = 0.0;
  auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
  if (number.empty() || ec != std::errc() || ptr != number.data() + number.size() || !(v > 0.0) ||
      !std::isfinite(v))
    throwInput(
        "--budget {}: expected milliseconds (> 0, e.g. 25) or a multiple of the none frame's "
        "median (e.g. 4x)",
        b);
  return {v, relative};
}

std::vector<Candidate> candidateGrid(const std::vector<std::string>& methods) {
  std::vector<Candidate> out;
  for (const std::string& m : methods) {
    out.push_back({m, {}, m});
    for (const GridPoint& g : gridPoints())
      if (g.method == m) out.push_back({m, g.params, methodText(m, g.params)});
  }
  return out;
}

std::vector<CalibrationView> calibrationViews(const Scene& scene, float time, int along) {
  std::vector<CalibrationView> out;
  const CameraDesc* walk = nullptr;
  for (const CameraDesc& c : scene.cameras) {
    out.push_back({c.at(time), time, c.name});
    if (!walk && !c.path.empty()) walk = &c;
  }
  if (!walk) return out;
  const float t0 = walk->path.keys.front().time, t1 = walk->path.keys.back().time;
  for (int k = 0; k < along; ++k) {
    const float t = t0 + (t1 - t0) * (float(k) + 0.5f) / float(along);
    out.push_back({walk->at(t), t, fmt::format("{}@{:.2f}s", walk->name, t)});
  }
  return out;
}

size_t Advice::totalPixels() const {
  size_t n = 0;
  for (size_t p : pixels) n += p;
  return n;
}

double Advice::psnr(double sse) const {
  return psnrFromMse(sse / double(std::max<size_t>(totalPixels(), 1)));
}

Advice advise(const Scene& scene, const AdviseSetup& setup) {
  return Advisor(scene, setup).run();
}

}  // namespace mirage::app
