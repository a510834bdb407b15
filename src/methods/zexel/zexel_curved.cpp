#include "methods/zexel/zexel_curved.h"

#include <algorithm>

#include <fmt/format.h>

#include "gpu/loop_budget.h"
#include "methods/recapture_params.h"
#include "methods/zexel/zexel_shared.h"
#include "render/base_colour.h"

namespace mirage {

namespace {

// --zexel-curved: curved reflectors inverse-warped (true), or in their base colour.
constexpr Choice<bool> kInverseWarp[] = {{"inverse", true}, {"base", false}};

}  // namespace

std::vector<ParamSpec> ZexelCurvedReflectors::params() {
  std::vector<ParamSpec> params = {
      ParamSpec::choice<bool>("zexel-curved", kInverseWarp, true,
                              "curved reflectors: inverse warping of a depth-preserving cube map "
                              "of each, or their base colour"),
      ParamSpec::integer("zexel-cube-size", 16, 2048, 256,
                         "face size of each curved reflector's depth-preserving cube map, "
                         "in texels"),
      ParamSpec::real("zexel-curved-step", 0.25, 16.0, 1.0,
                      "the inverse warp's step along the reflected ray's epipolar line in "
                      "the cube map, in texels"),
      ParamSpec::choice("zexel-curved-bounds", {"on", "off"}, "on",
                        "the inverse warp crosses stretches where the ray stays in front of the "
                        "map in one read of a pyramid of lower bounds of its distances (off: "
                        "every step read; the same hits)")};
  for (ParamSpec& spec : probeRecaptureParams()) params.push_back(std::move(spec));
  return params;
}

ZexelCurvedReflectors::ZexelCurvedReflectors(const MethodSetup& setup)
    : inverse_(setup.params.choice<bool>("zexel-curved", kInverseWarp)),
      size_(setup.params.integer("zexel-cube-size")),
      search_(zexelInverseSettings(size_, float(setup.params.real("zexel-curved-step")),
                                   setup.params.on("zexel-curved-bounds"))),
      cubes_(size_, GL_RGBA32F),
      recapture_(probeRecapture(setup.params)),
      program_(gpu::Program::graphics("render/shaders/fullscreen.vert",
                                      "methods/zexel/zexel_inverse.frag",
                                      {"MIRAGE_REFLECTOR_SCREEN 1"})),
      base_program_(baseColourProgram()),
      diffuse_(setup.gpu.scene().diffuseInstances()) {
  const Scene& scene = setup.gpu.scene();
  const std::vector<int> planar = planarReflectors(scene);
  for (int i : scene.reflectorInstances())
    if (std::find(planar.begin(), planar.end(), i) == planar.end()) curved_.push_back(i);
  if (!curved_.empty())
    gpu::checkLoopBudget(fmt::format("zexel's curved search (--zexel-cube-size {}, "
                                     "--zexel-curved-step {})",
                                     size_, setup.params.real("zexel-curved-step")),
                         zexelInverseLoopCost(search_));
  program_.set("u_step_angle", search_.step_angle);
  program_.set("u_max_steps", search_.max_steps);
  program_.set("u_max_slope", search_.max_slope);
  program_.set("u_texel_angle", search_.texel_angle);
}

void ZexelCurvedReflectors::update(FrameContext& frame) {
  if (!inverse_ || curved_.empty() || frame.settings.order == 0) return;
  // The cubes show every diffuse object, the other reflectors and the light.
  const std::vector<int> reflectors = frame.gpu.scene().reflectorInstances();
  const float radius = std::max(frame.gpu.bounds().radius(), 1e-3f);
  // The frame's alpha is the distance from the view's eye: from the centre here.
  const int captured =
      cubes_.updateAtReflectors(frame.gpu, frame.settings.mip, curved_, diffuse_, reflectors,
                                recapture_, radius, [&](int r, const View& v) {
                                  frame.passes.begin(v, frame.settings);
                                  frame.passes.drawDirect();
                                  frame.passes.drawReflectors(base_program_, curved_[size_t(r)]);
                                });
  // Every cube's pyramid again, however few were captured: one pass over the cubes, a small
  // part of one capture.
  if (captured > 0) distances_.build(cubes_.texture());
  // A map not captured again this frame is searched from where it was captured.
  centres_.clear();
  for (int instance : curved_)
    centres_.push_back(
        cubes_.centre(int(centres_.size()), frame.gpu.instanceBounds(instance).center()));
}

std::vector<int> ZexelCurvedReflectors::draw(FrameContext& frame) {
  std::vector<int> own;
  if (!inverse_ || frame.settings.order == 0 || centres_.empty()) return own;
  for (int instance : curved_)
    if (frame.owns(instance)) own.push_back(instance);
  if (own.empty()) return own;
  gbuffer_.begin(frame.target, frame.passes, frame.view, frame.settings);
  frame.passes.drawReflectorInstances(gbuffer_.reflectorProgram(), own);
  cubes_.bind(MIRAGE_UNIT_METHOD);
  distances_.bind();
  program_.set("u_top_level", std::min(search_.top_level, distances_.topLevel()));
  ShadeOptions options;
  options.own = &own;
  options.each = [&](int instance) {
    const size_t r = size_t(std::find(curved_.begin(), curved_.end(), instance) - curved_.begin());
    program_.set("u_layer", int(r));
    program_.set("u_centre", centres_[r]);
  };
  gbuffer_.shade(frame.target, frame.passes, frame.view, frame.settings, program_, options);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the counts, read back by the stats
  frame.target.bind();
  frame.passes.begin(frame.view, frame.settings);
  return own;
}

void ZexelCurvedReflectors::addStats(std::map<std::string, double>& stats,
                                     const std::vector<double>& counters) const {
  stats["zexel_curved_reflectors"] = inverse_ ? double(curved_.size()) : 0.0;
  const double rays = counters[MIRAGE_ZEXEL_COUNT_CURVED_RAYS];
  stats["zexel_curved_pixels"] = rays;
  stats["zexel_curved_reads_per_ray"] =
      rays > 0.0 ? counters[MIRAGE_ZEXEL_COUNT_CURVED_READS] / rays : 0.0;
  stats["zexel_cube_captures"] = double(cubes_.captures());
  stats["zexel_cubes_pending"] = double(cubes_.pending());
}

}  // namespace mirage
