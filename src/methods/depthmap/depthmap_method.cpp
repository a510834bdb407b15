#include "methods/depthmap/depthmap_method.h"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "gpu/memory.h"
#include "methods/depthmap/depthmap_capture.h"
#include "methods/depthmap/depthmap_loop_cost.h"
#include "methods/depthmap/depthmap_shared.h"
#include "methods/impostor/billboard_stage.h"
#include "methods/impostor/candidate_cells.h"
#include "methods/recapture_params.h"
#include "render/base_colour.h"

namespace mirage {

namespace {

// --depthmap-search linear: a walk of the full map (true), else the SRDM rows.
constexpr Choice<bool> kLinearSearch[] = {{"srdm", false}, {"linear", true}};
// --srdm-second: the search the shader compiles in for --srdm-rows 2 (DEPTHMAP_SEARCH).
constexpr Choice<int> kSecondRowSearches[] = {
    {"hit", MIRAGE_DEPTHMAP_SEARCH_HIT},
    {"interpolate", MIRAGE_DEPTHMAP_SEARCH_INTERPOLATE},
    {"hit-interpolate", MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE}};
constexpr Choice<SrdmBuilder> kSrdmBuilders[] = {{"cpu", SrdmBuilder::kCpu},
                                                 {"gpu", SrdmBuilder::kGpu}};

DepthMapOptions depthMapOptions(const ParamValues& params) {
  DepthMapOptions o;
  o.size = params.integer("depthmap-size");
  o.fov_degrees = float(params.real("depthmap-fov"));
  o.maps = params.integer("depthmap-maps");
  o.self_maps = params.integer("self-maps");
  return o;
}

// The search the shader compiles in (depthmap_shared.h, DEPTHMAP_SEARCH).
int depthMapSearch(const ParamValues& params) {
  if (params.choice<bool>("depthmap-search", kLinearSearch)) return MIRAGE_DEPTHMAP_SEARCH_LINEAR;
  if (params.integer("srdm-rows") == 1) return MIRAGE_DEPTHMAP_SEARCH_SRDM;
  return params.choice<int>("srdm-second", kSecondRowSearches);
}

SrdmSettings srdmSettings(const ParamValues& params) {
  SrdmSettings s;
  s.domains = params.integer("srdm-n");
  s.points = params.integer("srdm-m");
  s.simplifier = parseSrdmSimplifier(params.text("srdm-simplify"));
  return s;
}

// What depth maps cost per group and besides: per map a colour layer (mip-mapped), a depth
// layer and n SRDM layers, the SRDM array being the largest; the reflectors' maps of themselves
// (--self-maps) are fixed.
GroupCost depthMapCost(const Scene& scene, const DepthMapOptions& options,
                       const SrdmSettings& srdm) {
  int64_t self = 0;
  if (options.self_maps > 0)
    for (int r : scene.reflectorInstances())
      if (!isPlanarInstance(scene, r, scene.instances[size_t(r)].matrixAt(0.0f)))
        self += options.self_maps;
  const int w = options.size;
  const uint64_t map = gpu::storageBytes(GL_RGBA16F, w, w, 1, gpu::Texture::fullMipLevels(w)) +
                       gpu::storageBytes(GL_DEPTH_COMPONENT32F, w, w, 1, 1) +
                       gpu::storageBytes(GL_RGBA32F, (srdm.points + 1) / 2, w, srdm.domains, 1);
  GroupCost cost;
  cost.fixed_layers = self * srdm.domains;
  cost.layers_per_group = int64_t(options.maps) * srdm.domains;
  cost.fixed_bytes = uint64_t(self) * map;
  cost.bytes_per_group = uint64_t(options.maps) * map;
  return cost;
}

Grouping depthMapGroups(const MethodSetup& setup, const DepthMapOptions& options,
                        const SrdmSettings& srdm) {
  const Scene& scene = setup.gpu.scene();
  BillboardStageOptions stage = billboardStageOptions(setup.params);
  // The billboard stage beside the maps (the planar objects, the reflective billboards, its
  // captures' textures) takes its bytes from the same --impostor-memory.
  const std::vector<int> objects = depthMappedObjects(scene);
  stage.set.excluded = objects;
  stage.set.layers = sceneLayers(scene);
  GroupCost cost = depthMapCost(scene, options, srdm);
  cost.fixed_bytes += billboardStageCost(scene, stage).fixed_bytes;
  return chooseGroups(scene, objects, stage.groups, cost, impostorGroupCaps(stage), "depth maps",
                      "a smaller --srdm-n or --self-maps");
}

class DepthMapMethod final : public Method {
 public:
  explicit DepthMapMethod(const MethodSetup& setup)
      : options_(depthMapOptions(setup.params)),
        srdm_(srdmSettings(setup.params)),
        grouping_(depthMapGroups(setup, options_, srdm_)),
        specs_(placeDepthMaps(setup.gpu.scene(), options_, grouping_.memberLists())),
        stage_(stageOptions(setup.params, specs_), setup.gpu.scene()),
        capture_(options_, srdm_, setup.params.choice<SrdmBuilder>("srdm-builder", kSrdmBuilders)),
        recapture_(billboardRecapture(setup.params)),
        last_bounce_reflective_(lastBounceReflective(setup.params)),
        shader_("methods/depthmap/depthmap.frag", shaderDefines(specs_, setup.params, stage_),
                impostorPass(setup.params)),
        base_program_(baseColourProgram()),
        search_(depthMapSearch(setup.params)),
        tries_(setup.params.integer("depthmap-tries")),
        self_maps_(std::any_of(specs_.begin(), specs_.end(),
                               [](const DepthMapSpec& s) { return s.reflector; })
                       ? options_.self_maps
                       : 0) {}

  void update(FrameContext& frame) override {
    stage_.update(frame);
    GpuScene& gpu = frame.gpu;
    if (updated_ && updated_version_ == gpu.version() && capture_.pending() == 0) {
      last_captures_ = 0;
      return;
    }
    last_captures_ = capture_.update(gpu, frame.passes, specs_, frame.settings, recapture_);
    // The cameras follow their objects every time the scene moves; nothing is rebuilt for it.
    std::vector<shading::DepthMapData> data;
    for (size_t i = 0; i < specs_.size(); ++i) {
      const DepthMapSpec& s = specs_[i];
      const View view = depthMapView(s, gpu.instanceMatrix(s.instance), options_);
      shading::DepthMapData d{};
      d.view_proj = view.viewProjection();
      d.forward = vec4(view.forward(), 2.0f * std::tan(glm::radians(options_.fov_degrees) * 0.5f) /
                                           float(options_.size));
      int count = 0;
      if (s.index == 0)
        for (size_t k = i; k < specs_.size() && specs_[k].instance == s.instance; ++k) ++count;
      d.info = ivec4(int(i), int(i) * srdm_.domains, s.instance, count);
      d.bound = depthMapSphere(s, gpu.instanceMatrix(s.instance));
      data.push_back(d);
    }
    uploadLists(gpu, data);
    if (data.empty()) data.push_back(shading::DepthMapData{});
    maps_.upload(std::span<const shading::DepthMapData>(data));
    updated_ = true;
    updated_version_ = gpu.version();
  }

  void render(FrameContext& frame) override {
    passes_ = {};
    const ImpostorHookCost hooks{
        depthMapHookLoopCost(longest_list_, options_.maps, tries_, self_maps_,
                             mapSearchLoopCost(search_, srdm_.points, options_.size)),
        fmt::format(", lists of up to {} depth-mapped objects, --depthmap-maps {}, "
                    "--depthmap-tries {}, --self-maps {}, --srdm-m {}, --depthmap-size {}",
                    longest_list_, options_.maps, tries_, self_maps_, srdm_.points,
                    options_.size)};
    if (!stage_.beginFrame(frame, shader_, base_program_, last_bounce_reflective_, hooks)) return;
    maps_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_DEPTHMAPS);
    lists_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_DEPTHMAP_LISTS);
    capture_.colors().bind(MIRAGE_UNIT_DEPTHMAP_COLOR);
    capture_.srdms().bind(MIRAGE_UNIT_DEPTHMAP_SRDM);
    capture_.depths().bind(MIRAGE_UNIT_DEPTHMAP_DEPTH);
    shader_.set("u_depthmap_size", options_.size);
    shader_.set("u_srdm_n", srdm_.domains);
    shader_.set("u_srdm_m", srdm_.points);
    passes_ = shader_.draw(frame, gbuffer_);
  }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> out = stage_.stats();
    addPassStats(out, passes_);
    out["depth_maps"] = double(specs_.size());
    out["depthmap_groups"] = double(grouping_.groups.size());
    out["depthmap_objects"] = double(grouping_.objects);
    out["depthmap_layers"] = double(grouping_.layers);
    out["self_maps"] = double(std::count_if(specs_.begin(), specs_.end(),
                                            [](const DepthMapSpec& s) { return s.reflector; }));
    out["depthmap_color_captures"] = double(capture_.colorCaptures());
    out["depthmap_color_captures_last_update"] = double(last_captures_);
    out["depthmap_depth_captures"] = double(capture_.depthCaptures());
    out["srdm_builds"] = double(capture_.srdmBuilds());
    out["srdm_last_build_ms"] = capture_.lastBuildMs();
    out["srdm_dropped_samples"] = double(capture_.droppedSamples());
    return out;
  }

 private:
  // The objects' candidate lists per reflector and direction cell (MIRAGE_BIND_DEPTHMAP_LISTS):
  // each object by its maps' sphere, a reflector's maps of itself in its own lists only.
  void uploadLists(const GpuScene& gpu, const std::vector<shading::DepthMapData>& data) {
    const std::vector<int> reflectors = gpu.scene().reflectorInstances();
    std::vector<BoundingSphere> spheres;
    std::vector<int> owner, first_map;
    for (size_t i = 0; i < specs_.size(); ++i) {
      if (specs_[i].index != 0) continue;
      spheres.push_back({vec3(data[i].bound), data[i].bound.w});
      const auto self = std::find(reflectors.begin(), reflectors.end(), specs_[i].instance);
      owner.push_back(specs_[i].reflector ? int(self - reflectors.begin()) : -1);
      first_map.push_back(int(i));
    }
    const CellLists lists = cellLists(reflectorVertexSpheres(gpu.scene(), gpu.time()),
                                      stage_.set().cells, spheres, owner);
    const int head = 2 * int(lists.ranges.size());
    std::vector<int> words;
    longest_list_ = 0;
    for (const ivec2& range : lists.ranges) {
      words.push_back(head + range.x);
      words.push_back(range.y);
      longest_list_ = std::max(longest_list_, range.y);
    }
    for (int candidate : lists.entries) words.push_back(first_map[size_t(candidate)]);
    if (words.empty()) words.push_back(0);
    lists_.upload(std::span<const int>(words));
  }

  static std::vector<std::string> shaderDefines(const std::vector<DepthMapSpec>& specs,
                                                const ParamValues& params,
                                                const BillboardStage& stage) {
    std::vector<std::string> defines = stage.shaderDefines();
    defines.push_back("DEPTHMAP_SEARCH " + std::to_string(depthMapSearch(params)));
    defines.push_back("DEPTHMAP_TRIES " + std::to_string(params.integer("depthmap-tries")));
    if (std::any_of(specs.begin(), specs.end(), [](const DepthMapSpec& s) { return s.reflector; }))
      defines.push_back("DEPTHMAP_SELF");
    return defines;
  }

  static BillboardStageOptions stageOptions(const ParamValues& params,
                                            const std::vector<DepthMapSpec>& specs) {
    BillboardStageOptions o = billboardStageOptions(params);
    o.set.excluded = depthMappedInstances(specs);
    return o;
  }

  DepthMapOptions options_;
  SrdmSettings srdm_;
  Grouping grouping_;
  std::vector<DepthMapSpec> specs_;
  BillboardStage stage_;
  DepthMapCapture capture_;
  RecapturePolicy recapture_;  // the colour maps' re-shading, as the billboards'
  bool last_bounce_reflective_;
  ImpostorShader shader_;
  gpu::Program base_program_;
  ReflectorGBuffer gbuffer_;
  ReflectorPasses passes_;  // the last frame's
  gpu::Buffer maps_, lists_;
  int last_captures_ = 0;
  bool updated_ = false;
  uint64_t updated_version_ = 0;
  // What the trace's loops depend on (depthMapHookLoopCost): the search compiled in, the tries,
  // the self maps a reflector has (0 without), the longest list of objects.
  int search_ = MIRAGE_DEPTHMAP_SEARCH_SRDM, tries_ = 1, self_maps_ = 0;
  int longest_list_ = 0;
};

}  // namespace

MethodEntry depthmapMethodEntry() {
  MethodEntry entry;
  entry.info.name = "depthmap";
  entry.info.description =
      "depth-map impostors searched through simplified rotated depth maps (impostor paper, §4), "
      "with billboards for the rest";
  entry.info.min_order = 1;
  entry.info.params = {
      ParamSpec::integer("depthmap-size", 16, 2048, 256,
                         "side w of each depth map (colour and depth), in texels"),
      ParamSpec::real("depthmap-fov", 1.0, 90.0, 20.0,
                      "field of view of the depth-map cameras, in degrees"),
      ParamSpec::integer("depthmap-maps", 1, 6, 1,
                         "depth maps per object: 1 from the reflectors, 2 adds the opposite "
                         "side, up to 6 around; a ray tries them in order of how nearly each "
                         "looks along it"),
      ParamSpec::integer("depthmap-tries", 1, 6, 2,
                         "with several maps per object, how many a ray tries, in order of how "
                         "nearly each looks along it, until one is hit (1: the best-aligned "
                         "only; 2: then the next best)"),
      ParamSpec::integer("self-maps", 0, 6, 0,
                         "depth maps of each curved reflector of itself, for its "
                         "self-reflections (0 = none: a reflector never reflects itself)"),
      ParamSpec::integer("srdm-n", 1, 1024, 60, "rotated domains n (angular step 180/n degrees)"),
      ParamSpec::integer("srdm-m", 2, 256, 8,
                         "points m per simplified row (at most --depthmap-size)"),
      ParamSpec::choice("srdm-simplify", {"greedy", "fit"}, "greedy",
                        "row simplifier: the paper's greedy refinement, or its knots with "
                        "depths fitted by least squares"),
      ParamSpec::choice<SrdmBuilder>(
          "srdm-builder", kSrdmBuilders, SrdmBuilder::kCpu,
          "SRDM builder: multithreaded CPU from the depth read back (the faster "
          "on llvmpipe), or a compute shader on the depth array (greedy only)"),
      ParamSpec::choice<bool>("depthmap-search", kLinearSearch, false,
                              "ray-depth-map intersection: one SRDM row, or a walk of the full map "
                              "along the projected ray (the baseline)"),
      ParamSpec::integer("srdm-rows", 1, 2, 1,
                         "SRDM rows per search: 1 (the paper: the row through the projected "
                         "ray's midpoint), 2 (a second row, --srdm-second)"),
      ParamSpec::choice<int>(
          "srdm-second", kSecondRowSearches, MIRAGE_DEPTHMAP_SEARCH_HIT_INTERPOLATE,
          "what --srdm-rows 2 reads after the row through the projected ray's "
          "midpoint: hit, the row through that row's hit (its answer replaces the "
          "first); interpolate, instead of it the paper's two best rows (the two "
          "nearest domains' rows through the midpoint, depths interpolated by "
          "angle); hit-interpolate, the two best rows through the first row's hit")};
  for (const ParamSpec& p : billboardStageParams()) entry.info.params.push_back(p);
  entry.info.counters = {"depthmap_color_captures", "depthmap_depth_captures", "srdm_builds",
                         "billboard_captures", "environment_captures"};
  entry.info.frame_stats = BillboardStage::frameStats();
  entry.create = factoryOf<DepthMapMethod>();
  return entry;
}

}  // namespace mirage
