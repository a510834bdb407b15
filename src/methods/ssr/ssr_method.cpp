#include "methods/ssr/ssr_method.h"

#include <cmath>

#include "gpu/counter_slots.h"
#include "gpu/framebuffer.h"
#include "methods/probe_params.h"
#include "methods/recapture_params.h"
#include "methods/ssr/hiz_pyramid.h"
#include "methods/ssr/ssr_shared.h"
#include "render/depth_state.h"
#include "render/frame_target.h"
#include "render/probe_lookup.h"
#include "render/reflector_gbuffer.h"

namespace mirage {

namespace {

// What the screen-space pass reads beside the pyramid and the reflector G-buffer
// (render/reflector_gbuffer.h, which ssr draws the diffuse surfaces into too: a hit's normal
// tells a back face): the direct view's colour with the reflectors at their base colour (a hit
// on a reflector shows what order 1 shows there), copied from the frame.
struct ColorCopy {
  ColorCopy(ivec2 s, const FrameTarget& target) : size(s), color_id(target.color().id()) {
    color = gpu::Texture::create2D(GL_RGBA32F, s.x, s.y);  // the frame's format: copied from it
    color.setFilter(GL_LINEAR, GL_LINEAR);  // read at the refined hit, between pixel centres
  }
  bool fits(ivec2 s, const FrameTarget& target) const {
    return size == s && color_id == target.color().id();
  }
  ivec2 size;
  GLuint color_id;
  gpu::Texture color;
};

// The fallback method, made with ssr's own parameters (a superset of its).
std::unique_ptr<Method> makeFallback(const MethodSetup& setup) {
  const MethodEntry& fallback = findMethod(setup.params.text("ssr-fallback"));
  return fallback.create(
      MethodSetup{fallback.info, setup.gpu, setup.passes, setup.params, setup.settings});
}

// The screen-space pass's defines for the fallback's probe lookup (render/probe_lookup.h).
std::vector<std::string> fallbackDefines(const Scene& scene, const std::string& fallback) {
  return ProbeLookup::kindFor(scene, fallback == "envmap-box").defines();
}

class SsrMethod final : public Method {
 public:
  explicit SsrMethod(const MethodSetup& setup)
      : fallback_name_(setup.params.text("ssr-fallback")),
        // --ssaa N adds log2 N levels to the pyramid, and a ray about two cells per level (one
        // down, one across): steps + 2 log2 N keeps the share of rays that run out of steps at
        // native resolution's (docs/reports.md has the sweep).
        max_steps_(setup.params.integer("ssr-steps") +
                   2 * int(std::ceil(std::log2(double(setup.settings.pixel_scale))))),
        // A fraction of the scene's bounding radius, fixed for the method's life.
        thickness_(float(setup.params.real("ssr-thickness")) *
                   std::max(setup.gpu.scene().bounds().radius(), 1e-6f)),
        edge_fade_(float(setup.params.real("ssr-edge-fade"))),
        beyond_order_(setup.params.choice<BeyondOrder>("beyond-order", kBeyondOrders)),
        gbuffer_diffuse_(gpu::Program::graphics(
            "render/shaders/scene.vert", "render/shaders/diffuse.frag", {"MIRAGE_GBUFFER 1"})),
        fallback_(makeFallback(setup)),
        program_(gpu::Program::graphics("render/shaders/fullscreen.vert", "methods/ssr/ssr.frag",
                                        fallbackDefines(setup.gpu.scene(), fallback_name_))) {}

  void update(FrameContext& frame) override { fallback_->update(frame); }

  void render(FrameContext& frame) override {
    const ivec2 size = frame.view.size();
    if (!copy_ || !copy_->fits(size, frame.target))
      copy_ = std::make_unique<ColorCopy>(size, frame.target);
    drawGBuffer(frame);
    if (frame.settings.order > 0)
      glCopyImageSubData(frame.target.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, copy_->color.id(),
                         GL_TEXTURE_2D, 0, 0, 0, 0, size.x, size.y, 1);
    frame.beginPart(gpu::Part::kReflect);
    // Order 0: the reflectors keep the base colour the G-buffer drew them with.
    const ProbeLookup* probes = fallback_->probeLookup();
    if (frame.settings.order == 0 || !probes) return;
    hiz_.build(frame.target.depth(), size,
               HiZDepthRange{thickness_, frame.view.nearPlane(), frame.view.farPlane()});

    hiz_.texture().bind(MIRAGE_UNIT_SSR_HIZ);
    copy_->color.bind(MIRAGE_UNIT_SSR_COLOR);
    probes->bind(program_);
    counts_.resetAndBind(MIRAGE_BIND_SSR_COUNTS);
    program_.set("u_size", size);
    program_.set("u_levels", hiz_.levels());
    program_.set("u_max_steps", max_steps_);
    program_.set("u_edge_fade", edge_fade_);
    program_.set("u_near", frame.view.nearPlane());
    program_.set("u_far", frame.view.farPlane());
    program_.set("u_forward", frame.view.forward());
    // A reflector the screen shows at a hit is order 2: its probe shows it when that is asked.
    program_.set("u_beyond_probe",
                 beyond_order_ == BeyondOrder::kProbe && frame.settings.order > 1 ? 1 : 0);
    // Over the reflector pixels of the G-buffer; the target's alpha (eye distance) and reflector
    // ids are kept.
    ShadeOptions options;
    options.own = frame.own;
    gbuffer_.shade(frame.target, frame.passes, frame.view, frame.settings, program_, options);
    // The counts are atomics of the fragment shader: stats() reads them with
    // glGetNamedBufferSubData, which GL orders after the draw only behind this barrier (without
    // it, and without a glFinish between, llvmpipe returned zeros).
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  }

  int orderRendered(int requested) const override { return std::min(requested, 1); }

  // The direct part and the reflectors at their base colour into the frame, with the normals
  // beside. Inside `mixed` the frame holds the direct part already (frame.direct false): then
  // the diffuse surfaces there are drawn again for their normals, the same colour over the same.
  void drawGBuffer(FrameContext& frame) {
    if (frame.direct) frame.passes.drawBackground();
    gbuffer_.begin(frame.target, frame.passes, frame.view, frame.settings);
    if (frame.direct) {
      frame.passes.drawDiffuseWith(gbuffer_diffuse_);
    } else {
      DepthState equal(GL_EQUAL, false);  // the surfaces already in the depth buffer, again
      frame.passes.drawDiffuseWith(gbuffer_diffuse_);
    }
    frame.drawOwnReflectors(gbuffer_.reflectorProgram());  // inside `mixed`, the others draw theirs
  }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> s = fallback_->stats();
    if (!counts_.counted()) return s;
    const std::vector<double> c = counts_.sums();
    double pixels = 0.0;
    for (int k = 0; k < MIRAGE_SSR_OUTCOMES; ++k) pixels += double(c[size_t(k)]);
    const double share = pixels > 0 ? 1.0 / pixels : 0.0;
    auto fraction = [&](int k) { return double(c[size_t(k)]) * share; };
    s["ssr_reflector_pixels"] = pixels;
    s["ssr_hit_fraction"] = fraction(MIRAGE_SSR_HITS);
    s["ssr_faded_fraction"] = fraction(MIRAGE_SSR_FADED);
    s["ssr_off_screen_fraction"] = fraction(MIRAGE_SSR_OFF_SCREEN);
    s["ssr_no_hit_fraction"] = fraction(MIRAGE_SSR_NO_HIT);
    s["ssr_back_face_fraction"] = fraction(MIRAGE_SSR_BACK_FACE);
    s["ssr_out_of_steps_fraction"] = fraction(MIRAGE_SSR_OUT_OF_STEPS);
    s["ssr_steps_per_ray"] = double(c[MIRAGE_SSR_STEPS]) * share;
    // Every ray without a hit is the fallback's whole; a faded hit its share.
    const double missed = pixels - double(c[MIRAGE_SSR_HITS]) - double(c[MIRAGE_SSR_FADED]);
    s["ssr_fallback_fraction"] = (missed + double(c[MIRAGE_SSR_FADED_WEIGHT]) / 1024.0) * share;
    return s;
  }

 private:
  std::string fallback_name_;
  int max_steps_;
  float thickness_, edge_fade_;
  BeyondOrder beyond_order_;
  gpu::Program gbuffer_diffuse_;
  // The probes the screen-space pass shows where the screen has no data: the fallback method
  // keeps them up to date (update) and lends them (probeLookup); it never draws.
  std::unique_ptr<Method> fallback_;
  gpu::Program program_;
  ReflectorGBuffer gbuffer_;
  std::unique_ptr<ColorCopy> copy_;
  HiZPyramid hiz_;
  gpu::CounterSlots counts_{MIRAGE_SSR_COUNTS};
};

}  // namespace

MethodEntry ssrMethodEntry() {
  MethodEntry entry;
  entry.info.name = "ssr";
  entry.info.description =
      "screen-space reflections: each reflected ray marched through a hierarchical-Z pyramid of "
      "the direct view's depth, the hit pixel's colour, a reflection probe (--ssr-fallback) where "
      "the screen has no data; order 1 on the screen, a reflector it hits shaded with its probe";
  entry.info.max_order = 1;
  entry.info.params = {
      ParamSpec::integer("ssr-steps", 8, 4096, 256,
                         "ssr: the most pyramid cells a reflected ray visits before it gives up "
                         "(then the fallback shows)"),
      ParamSpec::real("ssr-thickness", 1e-4, 1.0, 0.02,
                      "ssr: how thick a surface of the depth buffer is taken to be, as a fraction "
                      "of the scene's bounding radius (a ray passing further behind misses it)"),
      ParamSpec::real("ssr-edge-fade", 0.0, 0.5, 0.1,
                      "ssr: width of the fade to the fallback at the screen's edges, as a fraction "
                      "of its shorter side"),
      ParamSpec::choice("ssr-fallback", {"envmap", "envmap-box"}, "envmap-box",
                        "ssr: the reflection probes shown where the screen has no data"),
      // The fallback's own parameters (envmap-box's, a superset of envmap's).
      envmapSizeParam(), probeProxyParam(), beyondOrderParam()};
  for (ParamSpec& spec : probeRecaptureParams()) entry.info.params.push_back(std::move(spec));
  entry.info.counters = {"cube_captures", "capture_passes"};
  entry.info.frame_stats = {"ssr_hit_fraction", "ssr_fallback_fraction", "ssr_steps_per_ray"};
  entry.create = factoryOf<SsrMethod>();
  return entry;
}

}  // namespace mirage
