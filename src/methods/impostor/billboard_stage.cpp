#include "methods/impostor/billboard_stage.h"

#include <algorithm>
#include <array>
#include <span>

#include <fmt/format.h>

#include "gpu/memory.h"
#include "methods/probe_params.h"
#include "methods/recapture_params.h"

namespace mirage {

namespace {

// --billboard-objects: billboards for every diffuse object (true), or for planar ones only.
constexpr Choice<bool> kAllObjects[] = {{"all", true}, {"planar", false}};
// --last-bounce: the last bounce tests every billboard (true), reflective ones included, or the
// diffuse ones only.
constexpr Choice<bool> kLastBounceReflective[] = {{"all", true}, {"diffuse", false}};

// What the billboards cost per group and besides: one surface layer per group and reflector;
// the planar objects' layers and the reflective billboards' (a surface and a surface-point
// layer for each ordered pair of reflectors) are fixed.
}  // namespace

GroupCost billboardStageCost(const Scene& scene, const BillboardStageOptions& options) {
  const BillboardedInstances instances = billboardedInstances(scene, options.set, 0.0f);
  const int64_t planar = int64_t(instances.planar.size() + instances.parts.size());
  const bool objects = !instances.objects.empty();
  const int64_t reflectors = int64_t(scene.reflectorInstances().size());
  const int size = options.billboard_size;
  const uint64_t surface =
      gpu::storageBytes(GL_RGBA16F, size, size, 1, gpu::Texture::fullMipLevels(size));
  const uint64_t position = gpu::storageBytes(GL_RGBA32F, size, size, 1, 1);
  const int64_t pairs = reflectors * (reflectors - 1);
  GroupCost cost;
  cost.fixed_layers = planar + pairs;
  cost.layers_per_group = objects ? reflectors : 0;
  cost.fixed_bytes = uint64_t(planar + pairs) * surface + uint64_t(pairs) * position;
  // The capture's depth buffer, and the environment of what has no billboard.
  cost.fixed_bytes += gpu::storageBytes(GL_DEPTH_COMPONENT32F, size, size, 1, 1);
  if (!instances.unbillboarded.empty() || options.set.morph_height > 0.0f) {
    const int env = options.envmap_size;
    cost.fixed_bytes +=
        6 * gpu::storageBytes(GL_RGBA16F, env, env, 1, gpu::Texture::fullMipLevels(env));
  }
  cost.bytes_per_group = objects ? uint64_t(reflectors) * surface : 0;
  return cost;
}

GroupCaps impostorGroupCaps(const BillboardStageOptions& options) {
  GroupCaps caps;
  caps.max_layers = driverArrayLayers();
  caps.max_bytes = options.memory_cap;
  return caps;
}

bool lastBounceReflective(const ParamValues& params) {
  return params.choice<bool>("last-bounce", kLastBounceReflective);
}

std::vector<ParamSpec> billboardStageParams() {
  std::vector<ParamSpec> params = {
      ParamSpec::integer("billboard-size", 16, 4096, 256,
                         "face size of each billboard texture, in texels"),
      ParamSpec::real("billboard-fov", 1.0, 60.0, 10.0,
                      "field of view of the billboard capture camera, in degrees"),
      ParamSpec::choice<bool>("billboard-objects", kAllObjects, true,
                              "which diffuse objects get billboards: all, or planar ones only (the "
                              "others are reflected through a captured environment map)"),
      ParamSpec::choice<bool>(
          "last-bounce", kLastBounceReflective, true,
          "what the last bounce tests: all billboards (a reflector hit shows its "
          "base colour, as the ray tracer at order K) or diffuse ones only (the "
          "paper's D + R - 1 + D count)"),
      ParamSpec::real("morph-height", 0.0, 1.0e6, 0.0,
                      "height of the transition walls that morph the ground billboard into the "
                      "environment (scene units; 0 = off)"),
      envmapSizeParam(),
      ParamSpec::text("impostor-groups", "auto|per-object|1..4096",
                      "impostor groups: objects clustered so that one billboard (per reflector) "
                      "or one set of depth maps covers each group; auto keeps one per object "
                      "while they fit the driver's texture layers, --impostor-memory and 64 "
                      "groups per reflector, else merges the smallest and most distant",
                      "auto"),
      ParamSpec::integer("impostor-memory", 16, 1 << 20, 2048,
                         "impostor textures auto grouping keeps within, in MiB"),
      ParamSpec::choice("impostor-sides", {"on", "off"}, "on",
                        "a planar reflector keeps a list of billboards for each side of its "
                        "plane, without those wholly on the other side, and a ray tests the "
                        "list of the side it leaves into (off: one list, every billboard)"),
      ParamSpec::integer("impostor-cells", 0, 16, 8,
                         "a reflector keeps its lists per cell of the directions its rays "
                         "leave along (N x N cells a cube face): each without the impostors "
                         "that no ray of the cell can reach (0: one list, every direction)"),
      impostorPassParam()};
  for (ParamSpec& spec : billboardRecaptureParams()) params.push_back(std::move(spec));
  return params;
}

BillboardStageOptions billboardStageOptions(const ParamValues& params) {
  BillboardStageOptions o;
  o.set.fov_degrees = float(params.real("billboard-fov"));
  o.set.objects = params.choice<bool>("billboard-objects", kAllObjects);
  o.set.morph_height = float(params.real("morph-height"));
  o.set.sides = params.on("impostor-sides");
  o.set.cells = params.integer("impostor-cells");
  o.billboard_size = params.integer("billboard-size");
  o.set.texels = o.billboard_size;
  o.envmap_size = params.integer("envmap-size");
  o.recapture = billboardRecapture(params);
  o.groups = parseGroupSetting(params.text("impostor-groups"), "--impostor-groups");
  o.memory_cap = uint64_t(params.integer("impostor-memory")) << 20;
  return o;
}

BillboardStage::BillboardStage(const BillboardStageOptions& options, const Scene& scene)
    : options_(options), capture_(options.billboard_size) {
  options_.set.layers = sceneLayers(scene);
  const BillboardedInstances instances = billboardedInstances(scene, options_.set, 0.0f);
  grouping_ = chooseGroups(
      scene, instances.objects, options_.groups, billboardStageCost(scene, options_),
      impostorGroupCaps(options_), "billboards",
      "a smaller --billboard-size, or fewer reflectors (--reflectors)");
  options_.set.groups = grouping_.memberLists();
}

void BillboardStage::update(FrameContext& frame) {
  GpuScene& gpu = frame.gpu;
  // Placements and captures depend on the scene's state only (its version): a frame that does
  // not change it (a camera move, a new mip setting) has nothing to redo, unless the budget left
  // drifted billboards for later frames.
  if (updated_ && updated_version_ == gpu.version() && capture_.pending() == 0) {
    last_captures_ = 0;
    return;
  }
  const Scene& scene = gpu.scene();
  set_ = placeBillboards(scene, gpu.time(), options_.set);
  ranges_.upload(std::span<const shading::BillboardRange>(set_.ranges));
  // An empty list still needs a buffer to bind.
  std::vector<int> entries = set_.entries;
  if (entries.empty()) entries.push_back(0);
  entries_.upload(std::span<const int>(entries));
  // The environment of what has no billboard is a capture kept under the billboards' policy and
  // budget too.
  const std::vector<int> env_instances = set_.environmentInstances();
  std::vector<Drift> env_drift;
  if (!env_instances.empty()) env_drift.push_back(environmentDrift(gpu, env_instances));
  std::vector<bool> env_due;
  last_captures_ = capture_.update(gpu, frame.passes, set_, frame.settings, options_.recapture,
                                   env_drift, &env_due);
  env_state_.nextFrame();
  if (!env_due.empty() && env_due[0]) captureEnvironment(frame, env_instances);
  std::vector<shading::BillboardData> data = set_.gpuData(scene);
  billboards_.upload(std::span<const shading::BillboardData>(data));
  std::vector<shading::BillboardCarry> carry = set_.carryData();
  carries_.upload(std::span<const shading::BillboardCarry>(carry));
  updated_ = true;
  updated_version_ = gpu.version();
}

void BillboardStage::bind(const gpu::Program& program, const GpuScene& gpu) const {
  billboards_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARDS);
  carries_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARD_CARRY);
  ranges_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARD_RANGES);
  entries_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARD_ENTRIES);
  capture_.surfaces().bind(MIRAGE_UNIT_BILLBOARD_SURFACE);
  capture_.positions().bind(MIRAGE_UNIT_BILLBOARD_POSITION);
  const bool captured_env = !set_.environmentInstances().empty();
  (captured_env ? environment_ : gpu.environment()).bind(MIRAGE_UNIT_BILLBOARD_ENV);
  program.set("u_ground", set_.ground);
  program.set("u_billboard_cells", set_.cells);
  if (set_.ground >= 0) {
    program.set("u_morph_min", set_.morph_box.lo);
    program.set("u_morph_max", set_.morph_box.hi);
    program.set("u_morph_centre", set_.environment_centre);
  }
}

int BillboardStage::longestList() const {
  int longest = 0;
  for (const shading::BillboardRange& r : set_.ranges)
    longest = std::max({longest, r.range.y + r.range.w, r.back.y + r.back.w});
  return longest;
}

bool BillboardStage::beginFrame(FrameContext& frame, const ImpostorShader& shader,
                                const gpu::Program& base_program, bool last_bounce_reflective,
                                const ImpostorHookCost& hooks) const {
  frame.drawDirect();
  frame.beginPart(gpu::Part::kReflect);
  if (frame.settings.order == 0 || empty()) {
    frame.drawOwnReflectors(base_program);
    return false;
  }
  gpu::checkLoopBudget(fmt::format("the impostor trace (--order {}, lists of up to {} "
                                   "billboards{})",
                                   frame.settings.order, longestList(), hooks.settings),
                       impostorTraceLoopCost(frame.settings.order, longestList(), hooks.cost));
  for (const gpu::Program* program : shader.programs()) {
    bind(*program, frame.gpu);
    program->set("u_last_bounce_reflective", last_bounce_reflective ? 1 : 0);
  }
  counts_.resetAndBind(MIRAGE_BIND_IMPOSTOR_COUNTS);
  return true;
}

std::vector<std::string> BillboardStage::shaderDefines() const {
  if (options_.set.morph_height > 0.0f) return {"IMPOSTOR_MORPH"};
  return {};
}

std::vector<std::string> BillboardStage::frameStats() {
  return {"impostor_candidates_per_ray", "impostor_rays_per_pixel"};
}

std::map<std::string, double> BillboardStage::stats() const {
  int diffuse = 0, reflective = 0;
  for (const BillboardSpec& b : set_.billboards)
    (b.kind == BillboardSpec::Kind::kReflective ? reflective : diffuse)++;
  const std::vector<double> c = counts_.sums();
  const double rays = double(c[MIRAGE_IMPOSTOR_RAYS]), pixels = double(c[MIRAGE_IMPOSTOR_PIXELS]);
  return {{"impostor_candidates_per_ray",
           rays > 0.0 ? double(c[MIRAGE_IMPOSTOR_CANDIDATES]) / rays : 0.0},
          {"impostor_rays_per_pixel", pixels > 0.0 ? rays / pixels : 0.0},
          {"impostor_pixels", pixels},
          {"billboard_captures", double(capture_.captures())},
          {"billboard_captures_last_update", double(last_captures_)},
          {"diffuse_billboards", double(diffuse)},
          {"reflective_billboards", double(reflective)},
          {"environment_captures", double(env_captures_)},
          {"billboards_pending", double(capture_.pending())},
          {"billboard_drift_degrees", double(capture_.largestDriftDegrees())},
          {"impostor_objects", double(grouping_.objects)},
          {"impostor_groups", double(grouping_.groups.size())},
          {"billboard_layers", double(set_.surface_layers + set_.position_layers)},
          {"billboard_list_entries", double(set_.entries.size())}};
}

// Diffuse objects without impostors (and the ground, when it morphs into the environment) are
// reflected through a cube map captured at the reflectors' centroid E, with the distant
// environment: a probe, whose drift (what it shows moved, turned or changed since its capture:
// render/recapture.h) the billboards' policy weighs with theirs. Like the billboards' surfaces
// it always has its full mip chain, so that the mip setting (which only picks the lookup's level
// in the shader) takes effect in the frame it changes, whatever it was at the capture.
Drift BillboardStage::environmentDrift(const GpuScene& gpu, const std::vector<int>& instances) {
  const int levels = gpu::Texture::fullMipLevels(options_.envmap_size);
  if (environment_.levels() != levels) {
    environment_ = gpu::Texture::createCube(GL_RGBA16F, options_.envmap_size, levels);
    env_state_.reset(1);
  }
  if (env_state_.size() == 0 || !env_state_.state(0).valid) {
    Drift invalid;
    invalid.invalid = true;
    return invalid;
  }
  return env_state_.drift(gpu, 0, set_.environment_centre, instances, options_.envmap_size);
}

void BillboardStage::captureEnvironment(FrameContext& frame, const std::vector<int>& instances) {
  GpuScene& gpu = frame.gpu;
  const Scene& scene = gpu.scene();
  const vec3 centre = set_.environment_centre;
  const int size = options_.envmap_size;
  if (!cube_) cube_ = std::make_unique<CubeCapture>(size);
  const float radius = std::max(scene.bounds(gpu.time()).radius(), 1e-3f);
  cube_->capture(environment_, 0, centre, 1e-3f * radius, 100.0f * radius, [&](const View& v) {
    frame.passes.begin(v, frame.settings);
    frame.passes.drawBackground();
    frame.passes.drawDiffuseInstances(instances);
  });
  environment_.generateMipmaps();
  env_state_.captured(gpu, 0, centre, instances);
  ++env_captures_;
}

}  // namespace mirage
