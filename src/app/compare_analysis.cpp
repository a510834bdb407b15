#include "app/compare_analysis.h"

#include <map>

#include <spdlog/spdlog.h>

#include "eval/metrics.h"
#include "raytrace/tracer.h"

namespace mirage::app {

namespace {

RayTracer& tracerAt(CompareRun& run, float time) {
  if (!run.tracer)
    run.tracer = std::make_unique<RayTracer>(*run.scene, run.renderer->environment());
  run.tracer->prepare(time);
  return *run.tracer;
}

// Relabels a region map's integer keys with names.
template <typename NameOf>
std::map<std::string, RegionMetrics> named(const std::map<uint32_t, RegionMetrics>& regions,
                                           NameOf name_of) {
  std::map<std::string, RegionMetrics> out;
  for (const auto& [label, r] : regions) out[name_of(label)] = r;
  return out;
}

// The layer regions of metrics.json (RegionSet::layers), by label (0: none).
constexpr const char* kLayerRegionNames[] = {"", "environment", "object", "reflectors"};

// The layer region of a reflector pixel of cause `label` whose first hit is `code`.
uint32_t layerLabel(const SceneLayers& layers, uint32_t label, uint32_t code) {
  switch (FirstHit(label)) {
    case FirstHit::kEnvironment:
      return 1;
    case FirstHit::kDiffuse:
      return layers.environment(firstHitInstance(code)) ? 1 : 2;
    case FirstHit::kSelf:
    case FirstHit::kReflector:
    case FirstHit::kBeyondOrder:
      return 3;
    default:
      return 0;  // none, unclassified
  }
}

void addCauses(const CompareRun& run, const Image& shown, const ReferenceFrame& reference,
               const Image2D<float>& ssim, const Image2D<float>& flip, RegionSet& regions) {
  const PixelCauses& causes = *reference.causes;
  regions.has_causes = true;
  regions.causes = named(regionMetrics(shown, reference.display, ssim, flip, causes.label),
                         [](uint32_t label) { return std::string(causeName(label)); });
  // The diffuse cause by the object its rays met: label = instance + 1; and by layer.
  const Scene& scene = *run.scene;
  IdImage objects(causes.code.width(), causes.code.height());
  IdImage layers(causes.code.width(), causes.code.height());
  IdImage mixed(causes.mixed.width(), causes.mixed.height());
  for (size_t i = 0; i < objects.pixelCount(); ++i) {
    const uint32_t label = causes.label.data()[i];
    if (label == uint32_t(FirstHit::kDiffuse))
      objects.data()[i] = uint32_t(firstHitInstance(causes.code.data()[i]) + 1);
    layers.data()[i] = layerLabel(run.layers, label, causes.code.data()[i]);
    mixed.data()[i] = label != 0 && causes.mixed.data()[i] ? 1u : 0u;
  }
  regions.layers = named(regionMetrics(shown, reference.display, ssim, flip, layers),
                         [](uint32_t label) { return std::string(kLayerRegionNames[label]); });
  regions.diffuse_objects =
      named(regionMetrics(shown, reference.display, ssim, flip, objects),
            [&](uint32_t label) { return objectName(scene, int(label - 1)); });
  const auto m = regionMetrics(shown, reference.display, ssim, flip, mixed);
  if (auto it = m.find(1); it != m.end())
    regions.mixed = it->second;
  else
    finishRegion(regions.mixed, 0.0, 0.0);  // no mixed pixel: figures NaN, as for any empty region
}

}  // namespace

std::string objectName(const Scene& scene, int instance) {
  const std::string& name = scene.instances[size_t(instance)].name;
  return name.empty() ? fmt::format("instance {}", instance) : name;
}

std::map<std::string, std::string> objectLayers(const Scene& scene, const SceneLayers& layers) {
  std::map<std::string, std::string> out;
  for (int i = 0; i < int(scene.instances.size()); ++i)
    if (!scene.isReflector(i)) out[objectName(scene, i)] = layers.name(i);
  return out;
}

std::vector<std::string> reflectorNames(const Scene& scene) {
  std::vector<std::string> names;
  std::map<std::string, int> uses;
  const std::vector<int> reflectors = scene.reflectorInstances();
  for (int i : reflectors) ++uses[scene.instances[size_t(i)].name];
  for (size_t r = 0; r < reflectors.size(); ++r) {
    const std::string& name = scene.instances[size_t(reflectors[r])].name;
    names.push_back(name.empty() || uses[name] > 1 ? fmt::format("{} #{}", name, r + 1) : name);
  }
  return names;
}

PixelCauses traceCauses(CompareRun& run, const View& frame_view, float time, const IdImage& mask) {
  RayTracer& tracer = tracerAt(run, time);
  return classifyCauses(tracer.firstHits(frame_view, run.settings.order), run.ssaa, mask);
}

ImageMetrics analyseFrame(const CompareRun& run, const Image& shown,
                          const ReferenceFrame& reference, RegionSet& regions,
                          Image2D<float>* flip) {
  Image2D<float> flip_map, ssim_map;
  ImageMetrics metrics =
      compareImages(shown, reference.display, reference.mask, &flip_map, &ssim_map);
  const std::vector<std::string>& names = run.report.reflector_names;
  regions.reflectors =
      named(regionMetrics(shown, reference.display, ssim_map, flip_map, reference.mask),
            [&](uint32_t id) {
              return id - 1 < names.size() ? names[id - 1] : fmt::format("reflector {}", id);
            });
  if (reference.causes) addCauses(run, shown, reference, ssim_map, flip_map, regions);
  if (flip) *flip = std::move(flip_map);
  return metrics;
}

void checkReference(CompareRun& run, const View& output_view, float time,
                    const ReferenceFrame& reference, int spp) {
  RayTracer& tracer = tracerAt(run, time);
  TraceSettings settings;
  settings.order = run.settings.order;
  settings.spp = spp;
  settings.jitter = true;  // stratified at random points: no position shared with --ssaa's grid
  const Image converged = toDisplay(tracer.render(output_view, settings).color, run.display);
  ReferenceInfo& info = run.report.reference_info;
  info.checked = true;
  info.converged_spp = spp;
  info.noise_floor_psnr = psnrFromMse(meanSquaredError(reference.display, converged));
  info.noise_floor_psnr_reflector =
      psnrFromMse(meanSquaredError(reference.display, converged, &reference.mask));
  spdlog::info(
      "reference check: the {}x{}-sub-pixel reference is {:.2f} dB (reflector pixels {:.2f} dB) "
      "from a converged {}-spp image",
      run.ssaa, run.ssaa, info.noise_floor_psnr, info.noise_floor_psnr_reflector, spp);
}

}  // namespace mirage::app
