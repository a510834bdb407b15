#include "methods/envmap/envmap_method.h"

#include <algorithm>

#include "gpu/buffer.h"
#include "methods/probe_params.h"
#include "methods/recapture_params.h"
#include "render/base_colour.h"
#include "render/probe_array.h"
#include "render/probe_lookup.h"
#include "shading/gpu_types.h"

namespace mirage {

namespace {

enum class Variant { kProbes, kBox, kInfinite };

std::vector<std::string> shaderDefines(Variant variant, const Scene& scene) {
  if (variant == Variant::kInfinite) return {"ENVMAP_INFINITE 1"};
  return ProbeLookup::kindFor(scene, variant == Variant::kBox).defines();
}

// A scene's probes in blend order (shading/probe_blend.h).
std::vector<ReflectionProbe> probesInBlendOrder(const Scene& scene) {
  std::vector<ReflectionProbe> out;
  for (int k : probeBlendOrder(scene.probes)) out.push_back(scene.probes[size_t(k)]);
  return out;
}

// What the blended lookup reads of probe `layer`.
shading::ProbeVolumeData volumeData(const ReflectionProbe& probe, int layer) {
  shading::ProbeVolumeData d;
  d.position = vec4(probe.position, float(layer));
  const ProbeVolume& inf = probe.influence;
  d.influence_lo = vec4(inf.sphere ? inf.centre : inf.box.lo, probe.blend_distance);
  d.influence_hi = vec4(inf.sphere ? vec3(0.0f) : inf.box.hi, inf.sphere ? inf.radius : 0.0f);
  const ProbeVolume& proxy = probe.proxy;
  d.proxy_lo = vec4(proxy.sphere ? proxy.centre : proxy.box.lo, 0.0f);
  d.proxy_hi = vec4(proxy.sphere ? vec3(0.0f) : proxy.box.hi, proxy.sphere ? proxy.radius : 0.0f);
  return d;
}

class EnvmapMethod final : public Method {
 public:
  EnvmapMethod(const MethodSetup& setup, Variant variant)
      : variant_(variant),
        infinite_(variant == Variant::kInfinite),
        size_(infinite_ ? 0 : setup.params.integer("envmap-size")),
        sphere_proxy_(variant == Variant::kBox &&
                      setup.params.choice<ProbeProxy>("proxy", kProbeProxies) ==
                          ProbeProxy::kSphere),
        scene_probes_(infinite_ ? std::vector<ReflectionProbe>{}
                                : probesInBlendOrder(setup.gpu.scene())),
        program_(gpu::Program::graphics("render/shaders/scene.vert", "methods/envmap/envmap.frag",
                                        shaderDefines(variant, setup.gpu.scene()))),
        base_program_(baseColourProgram()),
        diffuse_(setup.gpu.scene().diffuseInstances()),
        reflectors_(setup.gpu.scene().reflectorInstances()),
        recapture_(infinite_ ? RecapturePolicy{} : probeRecapture(setup.params)) {
    lookup_.box = variant == Variant::kBox;
    lookup_.sphere_proxy = sphere_proxy_;
    lookup_.centres = &centres_;
    if (!scene_probes_.empty()) {
      lookup_.blend = true;
      lookup_.volumes = &volumes_;
      lookup_.volume_count = int(scene_probes_.size());
      std::vector<shading::ProbeVolumeData> volumes;
      for (size_t k = 0; k < scene_probes_.size(); ++k)
        volumes.push_back(volumeData(scene_probes_[k], int(k)));
      volumes_.upload(std::span<const shading::ProbeVolumeData>(volumes));
    }
  }

  void update(FrameContext& frame) override {
    if (infinite_ || reflectors_.empty() || frame.settings.order == 0) return;
    const int levels = reflectors_.size() > 1 ? frame.settings.order : 1;
    if (int(levels_.size()) != levels) {
      levels_.clear();
      for (int l = 0; l < levels; ++l) levels_.push_back(std::make_unique<ProbeArray>(size_));
    }
    for (auto& level : levels_) level->allocate(probeCount(), frame.settings.mip);
    capture(frame);
  }

  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    if (frame.settings.order == 0) {
      frame.drawOwnReflectors(base_program_);
      return;
    }
    if (const ProbeLookup* lookup = probeLookup()) lookup->bind(program_);
    frame.drawOwnReflectors(program_);
  }

  const ProbeLookup* probeLookup() const override { return lookup_.probes ? &lookup_ : nullptr; }

  int orderRendered(int requested) const override {
    return infinite_ ? std::min(requested, 1) : requested;
  }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> s = {{"cube_captures", double(cube_captures_)},
                                       {"capture_passes", double(capture_passes_)},
                                       {"probes_pending", double(pending_)}};
    if (!infinite_) s["probes"] = probeCount();
    if (variant_ == Variant::kBox && scene_probes_.empty()) {
      const vec3 e = lookup_.proxy.extent();
      s["proxy_box_x"] = e.x;
      s["proxy_box_y"] = e.y;
      s["proxy_box_z"] = e.z;
    }
    return s;
  }

 private:
  // One probe per reflector (its own), or the scene's probes.
  int probeCount() const {
    return int(scene_probes_.empty() ? reflectors_.size() : scene_probes_.size());
  }

  // Level l of the probes shows the other reflectors through level l - 1 (level 0: at their base
  // colour), so the last of K levels holds K bounces. Every (level, probe) is one capture, made
  // again once what it shows drifted beyond the tolerances: the most drifted first, within the
  // budget, and a level's captures before the next level's within the frame.
  void capture(FrameContext& frame) {
    const size_t count = size_t(probeCount());
    std::vector<vec3> centres;
    std::vector<std::vector<int>> shown(count), shown_deep(count);
    for (size_t k = 0; k < count; ++k) {
      if (!scene_probes_.empty()) {
        // A scene's probe shows the same at every level (the reflectors in it through the level
        // below), but the reflectors that hold its position.
        centres.push_back(scene_probes_[k].position);
        shown[k] = shownByReflectionProbe(frame.gpu.scene(), scene_probes_[k],
                                          [&](int i) { return frame.gpu.instanceBounds(i); });
        shown_deep[k] = shown[k];
        continue;
      }
      centres.push_back(frame.gpu.instanceBounds(reflectors_[k]).center());
      shown[k] = shownByProbe(diffuse_, reflectors_, reflectors_[k]);
      // Deeper levels see the probe's own reflector too, in the others' probes.
      shown_deep[k] = shownByProbe(diffuse_, reflectors_, -1);
    }
    std::vector<Drift> drift;
    for (size_t l = 0; l < levels_.size(); ++l)
      for (const Drift& d : levels_[l]->drifts(frame.gpu, centres, l == 0 ? shown : shown_deep))
        drift.push_back(d);
    std::vector<int> due = chooseRecaptures(drift, recapture_);
    pending_ =
        int(chooseRecaptures(drift, {recapture_.angle_degrees, recapture_.texels, 0}).size()) -
        int(due.size());
    if (!due.empty()) captureDue(frame, due, centres, shown, shown_deep);
    for (auto& level : levels_) {
      level->finish();
      level->nextFrame();
    }
    if (boxed()) setUpBox(frame, *levels_.back());
    lookup_.probes = levels_.back().get();
  }

  // envmap-box with a probe at each reflector: one proxy box for all.
  bool boxed() const { return variant_ == Variant::kBox && scene_probes_.empty(); }

  // Captures the due (level, probe) units, a level's before the next level's.
  void captureDue(FrameContext& frame, std::vector<int> due, const std::vector<vec3>& centres,
                  const std::vector<std::vector<int>>& shown,
                  const std::vector<std::vector<int>>& shown_deep) {
    const int count = probeCount();
    std::stable_sort(due.begin(), due.end(), [&](int a, int b) { return a / count < b / count; });
    const float radius = std::max(frame.gpu.bounds().radius(), 1e-3f);
    int last_level = -1;
    for (int unit : due) {
      const int l = unit / count, r = unit % count;
      if (l != last_level && l > 0) {
        // The lookups of this level read the level below (the box's, captured where it was).
        levels_[size_t(l - 1)]->finish();
        if (boxed()) setUpBox(frame, *levels_[size_t(l - 1)]);
        lookup_.probes = levels_[size_t(l - 1)].get();
        lookup_.bind(program_);
      }
      if (l != last_level) ++capture_passes_;
      last_level = l;
      const gpu::Program& others = l == 0 ? base_program_ : program_;
      const std::vector<int>& what = (l == 0 ? shown : shown_deep)[size_t(r)];
      // A scene's probe draws the reflectors it shows (once per capture, not per face).
      std::vector<int> shown_reflectors;
      if (!scene_probes_.empty())
        for (int i : what)
          if (frame.gpu.scene().isReflector(i)) shown_reflectors.push_back(i);
      levels_[size_t(l)]->capture(frame.gpu, r, centres[size_t(r)], what, 1e-3f * radius,
                                  100.0f * radius, [&](int, const View& v) {
                                    frame.passes.begin(v, frame.settings);
                                    frame.passes.drawDirect();
                                    if (scene_probes_.empty())
                                      frame.passes.drawReflectors(others, reflectors_[size_t(r)]);
                                    else
                                      frame.passes.drawReflectorInstances(others, shown_reflectors);
                                  });
      ++cube_captures_;
    }
  }

  // The proxy of `envmap-box`: the bounds of the diffuse objects (the room), grown to hold every
  // probe centre, and the probe centres for the shader: where each probe of `level` (the one
  // looked up) was captured (in a moving scene, within the tolerances of where its reflector is
  // now).
  void setUpBox(FrameContext& frame, const ProbeArray& level) {
    Bounds3& box = lookup_.proxy;
    box = Bounds3{};
    for (int i : diffuse_) box.extend(frame.gpu.instanceBounds(i));
    std::vector<vec4> centres;
    for (size_t r = 0; r < reflectors_.size(); ++r) {
      const vec3 c = level.centre(int(r), frame.gpu.instanceBounds(reflectors_[r]).center());
      centres.push_back(vec4(c, 1.0f));
      box.extend(c);
    }
    centres_.upload(std::span<const vec4>(centres));
  }

  Variant variant_;
  bool infinite_;
  int size_;
  bool sphere_proxy_;
  std::vector<ReflectionProbe> scene_probes_;  // a scene's probes, in blend order (or none)
  gpu::Program program_, base_program_;
  // Level l of every reflector's probe; the frame looks up the last.
  std::vector<std::unique_ptr<ProbeArray>> levels_;
  gpu::Buffer centres_;  // envmap-box: vec4 probe centre per reflector
  gpu::Buffer volumes_;  // with a scene's probes: shading::ProbeVolumeData per probe
  // What the reflector pass (and Method::probeLookup's callers) binds: the last level's probes,
  // or, during captures, the level below the one captured; envmap-box's proxy and centres.
  ProbeLookup lookup_;
  std::vector<int> diffuse_;  // every diffuse instance: what the probes show besides reflectors
  std::vector<int> reflectors_;
  RecapturePolicy recapture_;
  int pending_ = 0;
  long cube_captures_ = 0, capture_passes_ = 0;
};

}  // namespace

MethodEntry envmapMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap";
  entry.info.counters = {"cube_captures", "capture_passes"};
  entry.info.description =
      "a cube map captured at each reflector's centre, looked up by direction (reflection probe)";
  entry.info.params = {envmapSizeParam()};
  for (ParamSpec& spec : probeRecaptureParams()) entry.info.params.push_back(std::move(spec));
  entry.create = factoryOf<EnvmapMethod>(Variant::kProbes);
  return entry;
}

MethodEntry envmapBoxMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap-box";
  entry.info.counters = {"cube_captures", "capture_passes"};
  entry.info.description =
      "the reflection probes looked up through a box proxy of the room (parallax-corrected cube "
      "map)";
  entry.info.params = {envmapSizeParam(), probeProxyParam()};
  for (ParamSpec& spec : probeRecaptureParams()) entry.info.params.push_back(std::move(spec));
  entry.create = factoryOf<EnvmapMethod>(Variant::kBox);
  return entry;
}

MethodEntry envmapInfiniteMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap-infinite";
  entry.info.description = "the scene's distant environment only (light probe at infinity)";
  entry.info.max_order = 1;
  entry.create = factoryOf<EnvmapMethod>(Variant::kInfinite);
  return entry;
}

}  // namespace mirage
