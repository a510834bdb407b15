#include "methods/zexel/zexel_method.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>

#include "core/error.h"
#include "gpu/counter_slots.h"
#include "methods/recapture_params.h"
#include "methods/zexel/zexel_cpu_warper.h"
#include "methods/zexel/zexel_curved.h"
#include "methods/zexel/zexel_maps.h"
#include "methods/zexel/zexel_resolve_pass.h"
#include "methods/zexel/zexel_shared.h"
#include "methods/zexel/zexel_splat_shared.h"
#include "methods/zexel/zexel_warp_pass.h"
#include "render/base_colour.h"
#include "render/mirror_images.h"
#include "render/recapture.h"

namespace mirage {

namespace {

// --zexel-warper cpu: the warp on CPU threads (true), else the compute shader.
constexpr Choice<bool> kCpuWarper[] = {{"gpu", false}, {"cpu", true}};
// --zexel-resolve: where a mirror's splats are blended (ZexelMethod::resolvePass).
enum class ResolveChoice { kAuto, kPass, kMirror };
constexpr Choice<ResolveChoice> kResolveChoices[] = {{"auto", ResolveChoice::kAuto},
                                                     {"pass", ResolveChoice::kPass},
                                                     {"mirror", ResolveChoice::kMirror}};

ZexelMapOptions mapOptions(const ParamValues& params) {
  ZexelMapOptions o;
  o.size = params.integer("zexel-size");
  o.count = params.integer("zexel-maps");
  o.cone = float(params.real("zexel-cone"));
  o.fov = float(params.real("zexel-fov"));
  o.hierarchy = params.on("zexel-lod");
  o.cpu_copies = params.choice<bool>("zexel-warper", kCpuWarper);
  return o;
}

// The driver's limits on the maps, checked before anything is allocated.
void checkDriverLimits(const ZexelMapOptions& o) {
  GLint largest = 0, layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  if (o.size > largest)
    throwGpu("zexel: --zexel-size {} is beyond the driver's GL_MAX_TEXTURE_SIZE ({})", o.size,
             largest);
  if (o.count > layers)
    throwGpu("zexel: --zexel-maps {} is beyond the driver's GL_MAX_ARRAY_TEXTURE_LAYERS ({})",
             o.count, layers);
}

GLuint newQuery() {
  GLuint id = 0;
  glCreateQueries(GL_SAMPLES_PASSED, 1, &id);
  return id;
}

// The splats' sizes (what the resolve's program is built for).
ZexelSplatOptions splatSizes(int splat, int pixel_scale) {
  ZexelSplatOptions o;
  o.splat = splat;
  o.unit = pixel_scale;
  return o;
}

// The mirror's program: reading what the resolve pass left (`gather` false), or gathering the
// splats itself (true: the gather's reach a constant, so that its loops unroll).
gpu::Program mirrorProgram(const ZexelSplatOptions& sizes, bool gather) {
  if (!gather)
    return gpu::Program::graphics("render/shaders/scene.vert", "methods/zexel/zexel_mirror.frag");
  return gpu::Program::graphics(
      "render/shaders/scene.vert", "methods/zexel/zexel_mirror.frag",
      {"ZEXEL_GATHER_IN_MIRROR", "ZEXEL_REACH " + std::to_string(zexelSplatReach(sizes)),
       std::string("ZEXEL_ALL_COVER ") + (zexelSplatsAllCover(sizes) ? "1" : "0")});
}

// Where a mirror's pixels are resolved (--zexel-resolve): auto takes the pass while the mirror's
// screen rectangle holds at most this many times the pixels the mirror showed the frame before.
constexpr double kResolvePassMostPixelsPerShown = 2.0;

// A planar mirror: its maps and this frame's warp of them.
struct ZexelMirror {
  ZexelMirrorMaps maps;
  ZexelWarpTarget target;
  // Its visible pixels: the samples its draw passes (no atomic in the shader), and how many it
  // showed when last drawn (-1: never).
  gpu::Handle<gpu::QueryTraits> pixels_query{newQuery()};
  bool drawn = false, resolved = false;  // this frame: drawn; resolved by the pass
  long shown_pixels = -1;
};

class ZexelMethod final : public Method {
 public:
  explicit ZexelMethod(const MethodSetup& setup)
      : options_(mapOptions(setup.params)),
        // Pixel sizes are output pixels (FrameSettings::pixel_scale: --ssaa).
        pixel_scale_(setup.settings.pixel_scale),
        per_frame_(std::min(setup.params.integer("zexel-maps-per-frame"), options_.count)),
        splat_(setup.params.integer("zexel-splat") * pixel_scale_),
        threads_(setup.params.integer("zexel-threads")),
        keep_(!setup.params.on("zexel-clear")),
        fill_(setup.params.integer("zexel-fill")),
        tolerance_(float(setup.params.real("zexel-depth-tolerance")) / 100.0f),
        resolve_choice_(setup.params.choice<ResolveChoice>("zexel-resolve", kResolveChoices)),
        warp_program_(gpu::Program::compute("methods/zexel/zexel_warp.comp")),
        pyramid_program_(gpu::Program::compute("methods/zexel/zexel_pyramid.comp")),
        mirror_program_(mirrorProgram(splatSizes(splat_, pixel_scale_), false)),
        gather_program_(mirrorProgram(splatSizes(splat_, pixel_scale_), true)),
        base_program_(baseColourProgram()),
        resolve_(splatSizes(splat_, pixel_scale_)),
        policy_(probeRecapture(setup.params)),
        curved_(setup) {
    checkDriverLimits(options_);
    for (int mirror : planarReflectors(setup.gpu.scene(), &not_planar_, "zexel"))
      mirrors_.push_back(std::make_unique<ZexelMirror>(ZexelMirror{{mirror, options_}, {}}));
  }

  // Captures a mirror's maps the first time and when the eye crossed to its other side; in a
  // moving scene once what they show drifted beyond the re-capture tolerances, seen from the
  // mirror's centre (nearer than the reference cameras: the angles are not underestimated), the
  // most drifted first within the probe budget: a mirror's maps count as one capture.
  void update(FrameContext& frame) override {
    curved_.update(frame);
    if (recapture_.size() != mirrors_.size()) recapture_.reset(mirrors_.size());
    std::vector<int> shown(frame.gpu.scene().instances.size());
    std::iota(shown.begin(), shown.end(), 0);  // the mirror too: its own motion re-captures
    // One zexel spans about fov / size; ProbeRecapture counts texels of 90° faces.
    const int face_size = std::max(int(float(options_.size) * 90.0f / options_.fov), 1);
    std::vector<Drift> drift(mirrors_.size());
    std::vector<vec3> points(mirrors_.size()), normals(mirrors_.size());
    for (size_t k = 0; k < mirrors_.size(); ++k) {
      const ZexelMirrorMaps& maps = mirrors_[k]->maps;
      if (!plane(frame, maps.mirror(), frame.view.eye(), points[k], normals[k])) continue;
      if (!maps.captured() || glm::dot(normals[k], maps.normal()) <= 0.0f)
        drift[k].invalid = true;
      else
        drift[k] = recapture_.drift(frame.gpu, int(k), mirrorCentre(frame, maps.mirror()), shown,
                                    face_size);
    }
    const std::vector<int> due = chooseRecaptures(drift, policy_);
    for (int k : due) {
      ZexelMirrorMaps& maps = mirrors_[size_t(k)]->maps;
      if (!scratch_) scratch_ = std::make_unique<FrameTarget>(ivec2(options_.size));
      maps.capture(frame, points[size_t(k)], normals[size_t(k)], *scratch_, base_program_,
                   pyramid_program_);
      recapture_.captured(frame.gpu, k, mirrorCentre(frame, maps.mirror()), shown);
      captures_ += maps.count();
    }
    maps_pending_ = int(chooseRecaptures(drift, {policy_.angle_degrees, policy_.texels, 0}).size() -
                        due.size());
    recapture_.nextFrame();
  }

  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    zexels_warped_ = tiles_warped_ = tile_levels_ = 0;
    counters_.resetAndBind(MIRAGE_BIND_ZEXEL_COUNTERS);
    std::vector<int> shown;
    for (auto& m : mirrors_) {
      if (m->drawn) m->shown_pixels = long(queryResult(m->pixels_query));
      m->drawn = frame.settings.order > 0 && frame.owns(m->maps.mirror()) && warp(frame, *m);
      if (!m->drawn) continue;
      draw(frame, *m);
      shown.push_back(m->maps.mirror());
    }
    for (int i : curved_.draw(frame)) shown.push_back(i);
    base_program_.use();
    for (int i : frame.gpu.scene().reflectorInstances())
      if (frame.owns(i) && std::find(shown.begin(), shown.end(), i) == shown.end())
        frame.gpu.draw(i);
  }

  int orderRendered(int requested) const override { return std::min(requested, 1); }

  std::map<std::string, double> stats() const override {
    const std::vector<double> counts = counters_.sums();
    double pixels = 0.0, passes = 0.0;
    for (const auto& m : mirrors_)
      if (m->drawn) {
        pixels += double(queryResult(m->pixels_query));
        passes += m->resolved ? 1.0 : 0.0;
      }
    std::map<std::string, double> s = {
        {"zexel_maps", double(options_.count) * double(mirrors_.size())},
        {"zexel_captures", double(captures_)},
        {"zexel_mirrors_pending", double(maps_pending_)},
        {"zexels_warped", double(zexels_warped_)},
        // The mean level of the tiles warped (0: every zexel of the full maps).
        {"zexel_level", tiles_warped_ > 0 ? double(tile_levels_) / double(tiles_warped_) : 0.0},
        {"mirror_pixels", pixels},
        {"zexel_resolve_passes", passes},
        {"exposed_fraction", pixels > 0 ? counts[MIRAGE_ZEXEL_COUNT_EXPOSED] / pixels : 0.0},
        {"reflectors_not_planar", double(not_planar_)}};
    curved_.addStats(s, counts);
    return s;
  }

 private:
  static vec3 mirrorCentre(const FrameContext& frame, int mirror) {
    return frame.gpu.instanceBounds(mirror).center();
  }

  static bool plane(FrameContext& frame, int mirror, const vec3& eye, vec3& point, vec3& normal) {
    return planarInstancePlane(frame.gpu.scene(), mirror,
                               frame.gpu.instanceMatrices()[size_t(mirror)], eye, point, normal);
  }

  // Warps the maps nearest the eye mirrored in `m` into its target; false (nothing warped) when
  // the mirror is edge-on or the eye is on the other side than the maps'.
  bool warp(FrameContext& frame, ZexelMirror& m) {
    vec3 point, normal;
    if (!m.maps.captured() || !plane(frame, m.maps.mirror(), frame.view.eye(), point, normal) ||
        glm::dot(normal, m.maps.normal()) <= 0.0f)
      return false;
    const View mirrored = frame.view.mirrored(point, normal);
    ZexelWarpJob job{
        &m.maps, m.maps.select(mirrored.eye(), per_frame_), splatOptions(frame, m), {}};
    // The tiles: at the coarsest level the mirror plane allows (no surface behind it lands
    // closer), at least ZEXEL_TILE_SPAN above level 0; each warps at most that many levels finer
    // (with the hierarchy off, level 0).
    const int top = m.maps.levels() - 1;
    job.splats.tile_level =
        std::min(top, options_.hierarchy
                          ? std::max(m.maps.levelFor(job.chosen.front(), mirrored, job.splats.goal),
                                     shading::ZEXEL_TILE_SPAN)
                          : shading::ZEXEL_TILE_SPAN);
    job.splats.finest =
        options_.hierarchy ? std::max(job.splats.tile_level - shading::ZEXEL_TILE_SPAN, 0) : 0;
    planZexelJob(job, mirrored);
    for (const ZexelTilePlan& plan : job.plans) {
      zexels_warped_ += plan.zexels;
      tiles_warped_ += plan.tiles;
      tile_levels_ += plan.level_sum;
    }
    m.target.resize(frame.view.size(), job.splats, keep_);
    if (options_.cpu_copies)  // the CPU warper: the maps were kept on the CPU for it
      warpOnCpu(job, mirrored, threads_, m.target);
    else
      warpOnGpu(warp_program_, job, mirrored, m.target);
    m.resolved = useResolvePass(job.splats.rect, m);
    if (m.resolved) resolve_.run(job.splats, m.target);
    return true;
  }

  // Whether mirror `m`'s pixels within `rect` are resolved by the compute pass (each cell
  // fetched once for three pixels, but every pixel of the rectangle resolved) or by the mirror's
  // shader (its visible pixels alone: the cheaper where the rectangle is much larger than them,
  // as for a mirror beside or behind the eye, whose bounds project to the whole screen).
  bool useResolvePass(const ivec4& rect, const ZexelMirror& m) const {
    if (resolve_choice_ != ResolveChoice::kAuto) return resolve_choice_ == ResolveChoice::kPass;
    const double area = double(std::max(rect.z - rect.x, 0)) * double(std::max(rect.w - rect.y, 0));
    return m.shown_pixels >= 0 && area <= kResolvePassMostPixelsPerShown * double(m.shown_pixels);
  }

  static GLuint queryResult(const gpu::Handle<gpu::QueryTraits>& query) {
    GLuint samples = 0;
    glGetQueryObjectuiv(query.id(), GL_QUERY_RESULT, &samples);
    return samples;
  }

  // How the zexels of mirror `m` become pixels this frame.
  ZexelSplatOptions splatOptions(const FrameContext& frame, const ZexelMirror& m) const {
    ZexelSplatOptions o = splatSizes(splat_, pixel_scale_);
    o.rect = screenRect(frame.view, frame.gpu.instanceBounds(m.maps.mirror()));
    o.lod = options_.hierarchy;
    // Zexels at most a pixel apart for 1x1 splats, two for larger or magnification-sized ones:
    // the splats still close the surface.
    o.goal = float(pixel_scale_) * (splat_ == pixel_scale_ ? 1.0f : 2.0f);
    o.tolerance = tolerance_;
    return o;
  }

  // The mirror with what its warp left around its pixels.
  void draw(FrameContext& frame, ZexelMirror& m) {
    const ZexelSplatOptions splats = splatOptions(frame, m);
    m.target.bindTexels();
    const gpu::Program& program = m.resolved ? mirror_program_ : gather_program_;
    program.set("u_keep", keep_ ? 1 : 0);
    program.set("u_fill", fill_);
    program.set("u_unit", pixel_scale_);
    program.set("u_rect", splats.rect);
    program.set("u_margin", zexelCellMargin(splats));
    if (!m.resolved) program.set("u_tolerance", splats.tolerance);
    program.use();
    glBeginQuery(GL_SAMPLES_PASSED, m.pixels_query.id());
    frame.gpu.draw(m.maps.mirror());
    glEndQuery(GL_SAMPLES_PASSED);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }

  ZexelMapOptions options_;
  int pixel_scale_, per_frame_, splat_, threads_;
  bool keep_;
  int fill_;
  float tolerance_;
  ResolveChoice resolve_choice_;
  gpu::Program warp_program_, pyramid_program_, mirror_program_, gather_program_, base_program_;
  ZexelResolvePass resolve_;
  gpu::CounterSlots counters_{MIRAGE_ZEXEL_COUNTERS};  // in slots (gpu/counter_slots.h)
  std::vector<std::unique_ptr<ZexelMirror>> mirrors_;
  std::unique_ptr<FrameTarget> scratch_;
  int not_planar_ = 0;
  RecapturePolicy policy_;
  ProbeRecapture recapture_;  // what each mirror's maps showed when captured
  int maps_pending_ = 0;
  long captures_ = 0, zexels_warped_ = 0, tiles_warped_ = 0, tile_levels_ = 0;
  ZexelCurvedReflectors curved_;  // the non-planar reflectors, by inverse warping
};

}  // namespace

MethodEntry zexelMethodEntry() {
  MethodEntry entry;
  entry.info.name = "zexel";
  entry.info.description =
      "depth-preserving reflection maps: per planar mirror maps of colour and distance from "
      "reference cameras on the hemisphere behind it, the nearest forward-warped (McMillan) to "
      "the mirrored eye each frame and splatted (surface splatting: the front surface's zexels "
      "blended), on the GPU or the CPU (forward-mapped planar mirror paper); non-planar "
      "reflectors inverse-warp a cube map of colour and distance";
  entry.info.max_order = 1;
  entry.info.counters = {"zexel_captures", "zexel_cube_captures"};
  entry.info.frame_stats = {"zexels_warped", "exposed_fraction", "zexel_resolve_passes",
                            "zexel_curved_pixels", "zexel_curved_reads_per_ray"};
  entry.info.params = {
      ParamSpec::integer("zexel-size", 16, 65536, 512,
                         "side of each depth-preserving reflection map, in zexels (at most the "
                         "driver's largest texture)"),
      ParamSpec::integer("zexel-maps", 1, 64, 1,
                         "reference maps per mirror on the hemisphere behind it (the paper: 1 "
                         "in the mirror room, up to 64 in the hall)"),
      ParamSpec::integer("zexel-maps-per-frame", 1, 2, 2,
                         "maps warped per mirror and frame, the nearest the mirrored eye"),
      ParamSpec::real("zexel-cone", 0.0, 85.0, kDefaultZexelCone,
                      "spread of the reference cameras from the mirror's axis, in degrees"),
      ParamSpec::real("zexel-fov", 10.0, 170.0, 100.0,
                      "vertical field of view of each reference camera, in degrees"),
      ParamSpec::integer("zexel-splat", 0, 9, 3,
                         "side of the square splat of a warped zexel, in pixels (the paper: 3; "
                         "0: from the warp's local magnification, up to 8)"),
      ParamSpec::choice("zexel-clear", {"on", "off"}, "on",
                        "clear the mirror's image each frame; off: exposures keep the last "
                        "frame's colour (the paper's don't-clear option)"),
      ParamSpec::integer("zexel-fill", 0, 64, 16,
                         "exposed mirror pixels show the farthest zexel met within this many "
                         "pixels in eight directions (0: no fill, the paper)"),
      ParamSpec::choice<bool>("zexel-warper", kCpuWarper, false,
                              "gpu: a compute shader; cpu: the same warp on parallel threads (the "
                              "same pixels whatever the threads)"),
      ParamSpec::integer("zexel-threads", 0, 256, 0, "threads of the CPU warper (0: all cores)"),
      ParamSpec::choice("zexel-lod", {"on", "off"}, "on",
                        "a mip-map-like hierarchy of the maps: each tile of a map warps the "
                        "coarsest level whose zexels land at most 1 (1x1 splats) or 2 pixels "
                        "apart on the warped surface (the paper's future work; off: every "
                        "zexel of the full map, the paper)"),
      ParamSpec::real("zexel-depth-tolerance", 0.0, 100.0, 2.0,
                      "zexels landing on a pixel within this many percent of the nearest's "
                      "distance are blended by their splat weights (surface splatting); 0: the "
                      "nearest only, the paper"),
      ParamSpec::choice<ResolveChoice>(
          "zexel-resolve", kResolveChoices, ResolveChoice::kAuto,
          "where the splats covering a mirror pixel are blended: pass, a compute "
          "pass over the mirror's screen rectangle before its draw (each cell "
          "fetched once for three pixels); mirror, the mirror's own shader (its "
          "visible pixels only); auto: the pass while the rectangle holds at most "
          "twice the pixels the mirror showed the frame before")};
  for (const ParamSpec& p : ZexelCurvedReflectors::params()) entry.info.params.push_back(p);
  entry.create = factoryOf<ZexelMethod>();
  return entry;
}

}  // namespace mirage
