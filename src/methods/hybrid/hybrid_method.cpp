#include "methods/hybrid/hybrid_method.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>

#include "core/error.h"
#include "core/timer.h"
#include "gpu/buffer.h"
#include "methods/hybrid/c3rc_frame.h"
#include "methods/hybrid/hybrid_shared.h"
#include "methods/hybrid/kd_gpu_cull.h"
#include "methods/hybrid/point_store.h"
#include "methods/hybrid/splat_pass.h"
#include "methods/probe_params.h"
#include "methods/recapture_params.h"
#include "render/base_colour.h"
#include "render/depth_state.h"
#include "render/probe_array.h"
#include "render/probe_lookup.h"

namespace mirage {

namespace {

// The choices of the binary parameters, each read once into the flag it sets.
constexpr Choice<bool> kCullOnGpu[] = {{"cpu", false}, {"gpu", true}};
constexpr Choice<bool> kFirstProjectionOnly[] = {{"all", false}, {"first", true}};
constexpr Choice<bool> kKeepBackfaces[] = {{"cull", false}, {"keep", true}};
constexpr Choice<bool> kEyeScaledRays[] = {{"eye", true}, {"unit", false}};

Culling parseCulling(const std::string& text) {
  if (text == "none") return Culling::kNone;
  if (text == "hull") return Culling::kHull;
  if (text == "inner") return Culling::kInner;
  return Culling::kExact;
}

PointSetOptions pointOptions(const ParamValues& params) {
  PointSetOptions o;
  o.total = params.integer("points");
  o.minimum = 200000;  // the default: low-polygon objects are topped up to this many points
  return o;
}

KdTreeOptions treeOptions(const ParamValues& params) {
  KdTreeOptions o;
  o.leaf_points = params.integer("kd-leaf-points");
  o.min_size = float(params.real("kd-min-size"));
  return o;
}

// --hybrid-lod auto: points with a projection per visible output pixel of a reflector triangle,
// the density that kept every reflected object of teapot-dragon, teapot-sphere, glass and
// concave-dish within 1 dB of every point (matched 2x2 sampling: docs/data/hybrid-lod/).
constexpr double kAutoLodDensity = 8.0;
// The probe's points a visible output pixel (each C3RC's projecting fraction).
constexpr double kProbeDensity = 1.0;
constexpr double kMostLodDensity = 1.0e6;

// --hybrid-lod: auto (kAutoLodDensity with the CPU culling; every point with the GPU traversal,
// which hands every kept point to the splatting), or a density in [0, kMostLodDensity] (0: every
// point), which the GPU traversal refuses.
double lodDensity(const std::string& text, bool cull_on_gpu) {
  if (text == "auto") return cull_on_gpu ? 0.0 : kAutoLodDensity;
  double density = -1.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, density);
  if (text.empty() || ec != std::errc() || ptr != end || !(density >= 0.0) ||
      density > kMostLodDensity)
    throwInput("--hybrid-lod '{}' is not allowed (allowed: auto, or 0..1e6 points a pixel)", text);
  if (cull_on_gpu && density > 0.0)
    throwInput(
        "hybrid: --hybrid-lod {} needs --hybrid-cull-on cpu (the GPU traversal hands every kept "
        "point to the splatting)",
        text);
  return density;
}

// --hybrid-min-pixels m in sub-pixels of an N x N supersampled frame: m output pixels' worth,
// except that the first pixel stays one sub-pixel — at native resolution m = 1 keeps every
// triangle that covers any pixel centre, so it must keep every triangle that covers any sub-pixel
// centre (N^2 would drop the triangles smaller than a pixel, which native resolution splats).
int minSubPixels(int m, int n) {
  return m == 0 ? 0 : (m - 1) * n * n + 1;
}

class HybridMethod final : public Method {
 public:
  explicit HybridMethod(const MethodSetup& setup)
      : store_(setup.gpu.scene(), pointOptions(setup.params), treeOptions(setup.params)),
        culling_(parseCulling(setup.params.text("hybrid-culling"))),
        first_only_(setup.params.choice<bool>("hybrid-projections", kFirstProjectionOnly)),
        keep_backfaces_(setup.params.choice<bool>("hybrid-backfaces", kKeepBackfaces)),
        eye_scaled_(setup.params.choice<bool>("c3rc-rays", kEyeScaledRays)),
        // Pixel sizes are output pixels: a frame supersampled N x N has N times the side and N^2
        // times the count of them (FrameSettings::pixel_scale).
        pixel_scale_(setup.settings.pixel_scale),
        splat_size_(setup.params.integer("splat-size") * pixel_scale_),
        min_pixels_(minSubPixels(setup.params.integer("hybrid-min-pixels"), pixel_scale_)),
        lod_density_(float(lodDensity(setup.params.text("hybrid-lod"),
                                      setup.params.choice<bool>("hybrid-cull-on", kCullOnGpu)) /
                           double(pixel_scale_ * pixel_scale_))),
        probe_density_(float(kProbeDensity / double(pixel_scale_ * pixel_scale_))),
        probes_(setup.params.integer("envmap-size")),
        recapture_(probeRecapture(setup.params)),
        splat_({first_only_, keep_backfaces_, splat_size_, pixel_scale_}),
        resolve_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                                "methods/hybrid/hybrid.frag",
                                                backgroundLookup().defines())),
        id_program_(
            gpu::Program::graphics("render/shaders/scene.vert", "methods/hybrid/triangle_id.frag")),
        base_program_(baseColourProgram()) {
    const Scene& scene = setup.gpu.scene();
    reflectors_ = scene.reflectorInstances();
    for (int i = 0; i < int(scene.instances.size()); ++i)
      if (!scene.isReflector(i) && !isPointSampled(i)) background_.push_back(i);
    if (store_.pointCount() > (size_t(1) << MIRAGE_HYBRID_INDEX_BITS))
      throwInput(
          "hybrid: {} point samples (the objects' mesh vertices) exceed the {} a winner word "
          "indexes; set --points (up to 4000000)",
          store_.pointCount(), size_t(1) << MIRAGE_HYBRID_INDEX_BITS);
    if (setup.params.choice<bool>("hybrid-cull-on", kCullOnGpu))
      gpu_cull_ = std::make_unique<KdGpuCull>(store_);
  }

  void update(FrameContext& frame) override {
    // The background probes show the objects without points, the reflectors and the light: a
    // point-sampled object that moves changes none of them (its tree lives in object space, and
    // the query moves instead).
    captureBackground(frame);
  }

  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    if (frame.settings.order == 0 || reflectors_.empty()) {
      frame.drawOwnReflectors(base_program_);
      return;
    }
    Stopwatch visibility;
    std::vector<std::vector<uint32_t>> pixels = visiblePixels(frame);
    visibility_ms_ = visibility.ms();

    C3rcFrameOptions options;
    options.min_pixels = min_pixels_;
    options.lod_density = lod_density_ > 0.0f ? probe_density_ : 0.0f;
    options.lod_minimum = kProbeMinimum;
    options.culling = culling_;
    options.cull_backfaces = !keep_backfaces_;
    options.eye_scaled = eye_scaled_;
    options.reach = reach(frame);
    options.cull_on_cpu = !gpu_cull_;
    std::vector<const Mesh*> meshes(frame.gpu.scene().instances.size());
    for (size_t i = 0; i < meshes.size(); ++i) meshes[i] = &frame.gpu.mesh(int(i));
    last_ = buildC3rcFrame(frame.gpu.scene(), reflectors_, pixels, frame.gpu.instanceMatrices(),
                           frame.view.eye(), store_, options, &meshes);
    if (gpu_cull_)
      gpu_last_ =
          gpu_cull_->run(last_.c3rcs, frame.gpu.instanceMatrices(), culling_, !keep_backfaces_);
    splat(frame);

    bindBackground(frame);
    DepthState visible(GL_LEQUAL, true);  // the visibility pass left the reflectors' depth
    frame.drawOwnReflectors(resolve_program_);
  }

  int orderRendered(int requested) const override { return std::min(requested, 1); }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> s;
    s["points"] = double(store_.pointCount());
    s["background_captures"] = double(probes_.captures());
    s["probes_pending"] = double(probes_.pending());
    s["point_sets"] = double(store_.clouds().size());
    s["point_sample_ms"] = store_.sampleMs();
    s["kd_build_ms"] = store_.buildMs();
    s["kd_leaves"] = double(store_.leafCount());
    s["kd_average_depth"] = store_.averageLeafDepth();
    s["kd_points_per_leaf"] = store_.pointsPerLeaf();
    s["c3rcs"] = double(last_.c3rcs.size() - size_t(last_.degenerate_triangles));
    s["c3rcs_multiple"] = double(last_.multiple_c3rcs);
    s["reflector_triangles_visible"] = double(last_.visible_triangles);
    s["reflector_triangles_small"] = double(last_.small_triangles);
    s["reflector_triangles_degenerate"] = double(last_.degenerate_triangles);
    const CullCounters& cull = gpu_cull_ ? gpu_last_.cull : last_.cull;
    s["cull_nodes_tested"] = double(cull.nodes_tested);
    s["cull_hull_rejects"] = double(cull.hull_rejects);
    s["cull_exact_rejects"] = double(cull.exact_rejects);
    s["cull_cone_rejects"] = double(cull.cone_rejects);
    s["cull_fold_keeps"] = double(cull.fold_keeps);
    s["cull_leaves_kept"] = double(cull.leaves_kept);
    s["splat_items"] = double(itemCount());
    s["cull_points_kept"] = double(last_.kept_points);
    s["lod_points"] = double(last_.lod_points);
    s["lod_probe_points"] = double(probe_points_);
    s["lod_probe_ms"] = probe_ms_;
    s["lod_c3rcs_dropped"] = double(last_.dropped_c3rcs);
    s["lod_items_dropped"] = double(last_.dropped_items);
    s["points_projected"] = double(splat_.counter(0));
    s["projections"] = double(splat_.counter(1));
    s["splats_written"] = double(splat_.counter(2));
    s["splat_candidates"] = double(splat_.counter(MIRAGE_HYBRID_COUNTER_CANDIDATES));
    s["points_with_projection"] = double(splat_.counter(3));
    s["points_facing_away"] = double(splat_.counter(4));
    s["valid_projection_fraction"] =
        splat_.counter(0) ? double(splat_.counter(3)) / double(splat_.counter(0)) : 0.0;
    s["projections_per_point"] =
        store_.pointCount() ? double(splat_.counter(1)) / double(store_.pointCount()) : 0.0;
    s["visibility_ms"] = visibility_ms_;
    // Both paths: the whole backward phase (C3RCs and culling); on the GPU path with the move
    // into the clouds' spaces (CPU) and the culling pass up to its glFinish and read-back.
    s["cull_ms"] = last_.ms + gpu_last_.transform_ms + gpu_last_.gpu_ms;
    s["cull_on_gpu"] = gpu_cull_ ? 1.0 : 0.0;
    if (gpu_cull_) {
      s["cull_gpu_ms"] = gpu_last_.gpu_ms;
      s["cull_transform_ms"] = gpu_last_.transform_ms;
      s["cull_gpu_dispatches"] = double(gpu_last_.dispatches);
    }
    s["splat_ms"] = splat_.ms() + probe_ms_;
    return s;
  }

 private:
  // The splatting pass's work items: from the CPU culling, or already on the GPU.
  size_t itemCount() const { return gpu_cull_ ? gpu_last_.items : last_.items.size(); }

  bool isPointSampled(int instance) const {
    for (const PointCloud& c : store_.clouds())
      if (c.points.instance == instance) return true;
    return false;
  }

  // The largest reflector-to-point distance: the diagonal of the reflectors' and the point
  // clouds' bounds together (not the scene's: a wide floor would stretch the root search for
  // nothing).
  float reach(const FrameContext& frame) const {
    Bounds3 b;
    for (int r : reflectors_) b.extend(frame.gpu.instanceBounds(r));
    for (const PointCloud& c : store_.clouds())
      b.extend(frame.gpu.instanceBounds(c.points.instance));
    return std::max(2.0f * b.radius(), 1e-3f);
  }

  // How the resolve pass looks the background up: through the box proxy of what it shows.
  static ProbeLookup backgroundLookup() {
    ProbeLookup lookup;
    lookup.box = true;
    return lookup;
  }

  // Binds the background for the resolve pass: the probes, where each was captured, and the
  // proxy — the bounds of what they show (the environment, the objects without points), open
  // where they do not enclose the probes (openProxy).
  void bindBackground(FrameContext& frame) {
    ProbeLookup lookup = backgroundLookup();
    lookup.probes = &probes_;
    lookup.centres = &centres_;
    std::vector<vec4> centres;
    Bounds3 around;  // the probe centres
    for (size_t r = 0; r < reflectors_.size(); ++r) {
      const vec3 c = probes_.centre(int(r), frame.gpu.instanceBounds(reflectors_[r]).center());
      centres.push_back(vec4(c, 1.0f));
      around.extend(c);
    }
    centres_.upload(std::span<const vec4>(centres));
    Bounds3 shown;
    for (int i : background_) shown.extend(frame.gpu.instanceBounds(i));
    lookup.proxy = openProxy(shown, around, 1e4f * std::max(frame.gpu.bounds().radius(), 1.0f));
    lookup.bind(resolve_program_);
  }

  // The background every reflector shows where no point lands: a cube map at its centre of
  // everything but the point-sampled objects and itself, other reflectors in base colour.
  void captureBackground(FrameContext& frame) {
    // Near and far from the bounds of what the probes show, so that the capture depends on
    // nothing else (a point-sampled object that moves leaves it exactly as it was).
    Bounds3 bounds;
    for (const std::vector<int>* list : {&background_, &reflectors_})
      for (int i : *list) bounds.extend(frame.gpu.instanceBounds(i));
    const float radius = std::max(bounds.empty() ? 1.0f : bounds.radius(), 1e-3f);
    probes_.updateAtReflectors(frame.gpu, frame.settings.mip, reflectors_, background_, reflectors_,
                               recapture_, radius, [&](int r, const View& v) {
                                 frame.passes.begin(v, frame.settings);
                                 frame.passes.drawBackground();
                                 frame.passes.drawDiffuseInstances(background_);
                                 frame.passes.drawReflectors(base_program_, reflectors_[size_t(r)]);
                               });
  }

  // Draws the reflectors into the frame's depth and a triangle-ID image, reads the IDs back and
  // counts the visible pixels of every reflector triangle.
  std::vector<std::vector<uint32_t>> visiblePixels(FrameContext& frame) {
    const ivec2 size = frame.target.size();
    if (!ids_fbo_ || ids_size_ != size) {
      ids_ = gpu::Texture::create2D(GL_RG32UI, size.x, size.y);
      ids_.setFilter(GL_NEAREST, GL_NEAREST);  // an integer texture is incomplete with linear
      ids_fbo_ = std::make_unique<gpu::Framebuffer>();
      ids_fbo_->attachColor(0, ids_);
      ids_fbo_->attachDepth(frame.target.depth());
      ids_fbo_->setDrawBuffers(1);
      ids_fbo_->checkComplete("hybrid triangle IDs");
      ids_size_ = size;
    }
    ids_fbo_->bind();
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferuiv(ids_fbo_->id(), GL_COLOR, 0, zero);
    frame.drawOwnReflectors(id_program_);
    // Kept between frames: a fresh 2.9 MB vector a frame (720x512) cost 8 ms of page faults and
    // zeroing on llvmpipe's machine, three times the pass itself.
    std::vector<uvec2>& ids = ids_pixels_;
    ids.resize(size_t(size.x) * size_t(size.y));
    ids_.downloadLayer(0, 0, GL_RG_INTEGER, GL_UNSIGNED_INT, ids.data(),
                       ids.size() * sizeof(uvec2));
    frame.target.bind();

    const Scene& scene = frame.gpu.scene();
    std::vector<int> slot(scene.instances.size(), -1);
    std::vector<std::vector<uint32_t>> pixels(reflectors_.size());
    for (size_t r = 0; r < reflectors_.size(); ++r) {
      slot[size_t(reflectors_[r])] = int(r);
      pixels[r].assign(frame.gpu.mesh(reflectors_[r]).triangleCount(), 0);
    }
    for (const uvec2& id : ids) {
      if (id.x == 0) continue;
      const int r = slot[id.x - 1];
      if (r >= 0 && id.y < pixels[size_t(r)].size()) ++pixels[size_t(r)][id.y];
    }
    return pixels;
  }

  void splat(FrameContext& frame) {
    SplatItems items;
    items.count = itemCount();
    probe_ms_ = 0.0;
    probe_points_ = 0;
    if (gpu_cull_) {
      items.gpu = &gpu_cull_->items();
      items.gpu_points = store_.largestLeaf();
    } else {
      items.cpu = &last_.items;
      if (lod_density_ > 0.0f && items.count > 0) {
        // The level of detail counts the points that can show: a probe through kProbeDensity
        // points a pixel finds each C3RC's projecting fraction, then the strides take
        // lod_density_ of those a pixel (restrideByProjections).
        splat_.run(frame, store_, last_.c3rcs, ids_, items, true);
        checkEveryPairProjected();
        probe_ms_ = splat_.ms();
        probe_points_ = last_.lod_points;
        restrideByProjections(last_, splat_.seenPerItem(last_.items.size()), lod_density_);
        items.count = last_.items.size();
      }
    }
    splat_.run(frame, store_, last_.c3rcs, ids_, items);
    checkEveryPairProjected();
  }

  // The splatting shader counts the (point, C3RC) pairs it projected. Its runs keep every
  // invocation within the loop budget (gpu/loop_budget.h), so fewer than the items hold is a
  // bug of ours (a run that overran llvmpipe's loop limiter, which cuts loops without a word):
  // an error, not a frame with reflections silently missing. A GPU's division may round an
  // item's strided count (hybrid_taken_points) the other way: a slack of one per item.
  void checkEveryPairProjected() const {
    const long long projected = splat_.counter(0);
    const long long expected = gpu_cull_ ? gpu_last_.points : last_.lod_points;
    if (std::llabs(projected - expected) > (long long)itemCount())
      throwRuntime(
          "hybrid: the splatting pass projected {} of the {} (point, C3RC) pairs it was given",
          projected, expected);
  }

  PointStore store_;
  Culling culling_;
  bool first_only_, keep_backfaces_, eye_scaled_;
  int pixel_scale_, splat_size_, min_pixels_;
  float lod_density_;    // points with a projection a sub-pixel (0: every point)
  float probe_density_;  // points the probe takes a sub-pixel
  ProbeArray probes_;    // the background, one cube per reflector
  gpu::Buffer centres_;  // vec4 per reflector: where its background probe was captured
  RecapturePolicy recapture_;
  SplatPass splat_;
  gpu::Program resolve_program_, id_program_, base_program_;
  std::vector<int> reflectors_, background_;
  gpu::Texture ids_;
  std::unique_ptr<gpu::Framebuffer> ids_fbo_;
  ivec2 ids_size_{0, 0};
  std::vector<uvec2> ids_pixels_;  // the triangle IDs read back, reused frame to frame
  C3rcFrame last_;
  std::unique_ptr<KdGpuCull> gpu_cull_;  // --hybrid-cull-on gpu
  KdGpuCullResult gpu_last_;
  double visibility_ms_ = 0.0;
  double probe_ms_ = 0.0;
  long long probe_points_ = 0;
};

}  // namespace

MethodEntry hybridMethodEntry() {
  MethodEntry entry;
  entry.info.name = "hybrid";
  entry.info.description =
      "point samples in kd-trees projected through a continuous 3-ray camera per reflector "
      "triangle and splatted, over a cube map of the rest (hybrid backward-forward paper)";
  entry.info.max_order = 1;
  entry.info.counters = {"background_captures"};
  entry.info.frame_stats = {"c3rcs",
                            "cull_leaves_kept",
                            "cull_hull_rejects",
                            "cull_exact_rejects",
                            "points_projected",
                            "splats_written"};
  entry.info.params = {
      ParamSpec::integer(
          "points", 0, 4000000, 0,
          "point samples over all reflected objects (0: their mesh vertices, topped up by "
          "surface samples to 200,000 where they are fewer)"),
      ParamSpec::integer("kd-leaf-points", 8, 65536, 256,
                         "kd-tree: a node with at most this many points is a leaf"),
      ParamSpec::real("kd-min-size", 0.0, 1.0, 0.0,
                      "kd-tree: a node smaller than this fraction of its object's diagonal is a "
                      "leaf"),
      ParamSpec::choice("hybrid-culling", {"inner", "exact", "hull", "none"}, "inner",
                        "view-volume culling of kd-tree boxes: hull planes, then the exact test "
                        "at inner nodes (inner) or at every node (exact); the hull planes only; "
                        "or none (every point through every C3RC)"),
      ParamSpec::choice<bool>(
          "hybrid-cull-on", kCullOnGpu, false,
          "where the kd-trees are culled: on the CPU (TBB, adjacent leaves merged "
          "into longer items) or by a compute shader (the same tests; slower on "
          "llvmpipe)"),
      ParamSpec::choice<bool>("hybrid-projections", kFirstProjectionOnly, false,
                              "splat every projection of a point within a C3RC, or the first only "
                              "(the paper's one fragment per point)"),
      ParamSpec::choice<bool>("hybrid-backfaces", kKeepBackfaces, false,
                              "points of a closed object facing away from a reflector triangle: "
                              "skipped before the projection (hidden; open surfaces keep them), or "
                              "projected as the paper does"),
      ParamSpec::choice<bool>(
          "c3rc-rays", kEyeScaledRays, true,
          "construction rays' lengths: the vertex's distance to the eye (exact on "
          "planar mirrors) or unit (the paper's)"),
      ParamSpec::integer("splat-size", 0, MIRAGE_HYBRID_MAX_SPLAT, 0,
                         "side of the square splat in pixels (0: from the point spacing and the "
                         "local magnification, at most 8)"),
      ParamSpec::integer("hybrid-min-pixels", 0, 1000000, 1,
                         "reflector triangles with fewer visible pixels show the environment"),
      ParamSpec::text("hybrid-lod", "auto|0..1e6",
                      "level of detail: take the points of a reflector triangle's view volume so "
                      "that about this many a visible pixel have a projection (a probe finds the "
                      "fraction that does; a uniform subsample with larger splats; 0: all; "
                      "auto: 8 with --hybrid-cull-on cpu, all with gpu)",
                      "auto"),
      envmapSizeParam()};
  for (ParamSpec& spec : probeRecaptureParams()) entry.info.params.push_back(std::move(spec));
  entry.create = factoryOf<HybridMethod>();
  return entry;
}

}  // namespace mirage
