#include "methods/planar/planar_method.h"

#include <memory>

#include "methods/planar/planar_probes.h"
#include "methods/probe_params.h"
#include "methods/recapture_params.h"
#include "render/base_colour.h"
#include "render/mirror_images.h"

namespace mirage {

namespace {

// --planar-curved: what a reflector that is not planar shows in a mirrored view.
enum class Curved { kAuto, kBase, kProbes };
constexpr Choice<Curved> kCurved[] = {
    {"auto", Curved::kAuto}, {"base", Curved::kBase}, {"probes", Curved::kProbes}};

bool probesFor(const MethodSetup& setup) {
  const Curved c = setup.params.choice<Curved>("planar-curved", kCurved);
  return c == Curved::kProbes || (c == Curved::kAuto && setup.composite);
}

class PlanarMethod final : public Method {
 public:
  explicit PlanarMethod(const MethodSetup& setup)
      : program_(gpu::Program::graphics("render/shaders/scene.vert",
                                        "render/shaders/mirror_image.frag")),
        base_program_(baseColourProgram()),
        planar_(planarReflectors(setup.gpu.scene(), &not_planar_, "planar")) {
    if (probesFor(setup) && not_planar_ > 0)
      probes_ = std::make_unique<PlanarProbes>(setup.gpu.scene(), planar_,
                                               setup.params.integer("envmap-size"),
                                               probeRecapture(setup.params));
  }

  // Nothing captured for the mirrors (every frame is drawn anew); with --planar-curved probes,
  // the curved reflectors' probes when the scene changed.
  void update(FrameContext& frame) override {
    if (probes_) probes_->update(frame, base_program_);
  }

  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    mirrored_views_ = 0;
    drawReflectors(frame, frame.view, frame.target, frame.settings.order, 0, -1,
                   ivec4(0, 0, frame.view.size()));
    glDisable(GL_SCISSOR_TEST);
  }

  std::map<std::string, double> stats() const override {
    return {{"planar_reflectors", double(planar_.size())},
            {"reflectors_not_planar", double(not_planar_)},
            {"mirrored_views", double(mirrored_views_)},
            {"cube_captures", probes_ ? double(probes_->captures()) : 0.0}};
  }

 private:
  // Draws every reflector of `view` into `target` (its direct part already drawn): each planar
  // one facing the eye shows the scene rendered from the eye mirrored in it, with `order` - 1
  // more bounces inside; the rest, and all of them at order 0, show their base colour.
  // `level` picks the images of this depth of recursion; `from` is the mirror `view` was
  // mirrored in (it cannot see itself). Only the pixels of `rect` (window coordinates, [xy, zw))
  // are drawn: a mirrored view is drawn within its mirror's screen rectangle (the scissor, as the
  // paper's stencil: the pixels outside are never shown), nested ones within their parents'.
  void drawReflectors(FrameContext& frame, const View& view, const FrameTarget& target, int order,
                      int level, int from, ivec4 rect) {
    std::vector<MirrorImage> shown;
    if (order > 0) {
      for (size_t k = 0; k < planar_.size(); ++k) {
        const int mirror = planar_[k];
        if (mirror == from || (level == 0 && !frame.owns(mirror))) continue;
        vec3 point, normal;
        if (!planarInstancePlane(frame.gpu.scene(), mirror,
                                 frame.gpu.instanceMatrices()[size_t(mirror)], view.eye(), point,
                                 normal))
          continue;
        const ivec4 r = screenRect(view, frame.gpu.instanceBounds(mirror));
        const ivec4 inner(glm::max(ivec2(r), ivec2(rect)),
                          glm::min(ivec2(r.z, r.w), ivec2(rect.z, rect.w)));
        if (inner.x >= inner.z || inner.y >= inner.w) continue;  // off screen
        const View mirrored = view.mirrored(point, normal);
        const FrameTarget& image = imageFor(level, k, view.size());
        image.bind();
        scissor(inner);
        image.clear();
        frame.passes.begin(mirrored, frame.settings);
        frame.passes.drawDirect();
        ++mirrored_views_;
        drawReflectors(frame, mirrored, image, order - 1, level + 1, mirror, inner);
        shown.push_back({mirror, &image});
      }
    }
    target.bind();
    scissor(rect);
    frame.passes.begin(view, frame.settings);
    // The mirror this view is mirrored in lies on its near plane: never drawn in it. The eye
    // view shows only this method's own reflectors; a mirrored view with a bounce left shows the
    // curved ones through their probes (--planar-curved probes).
    const bool through_probes = probes_ && level > 0 && order > 0;
    drawMirrorImages(frame.gpu, shown, program_, base_program_, from,
                     level == 0       ? frame.own
                     : through_probes ? &planar_
                                      : nullptr);
    if (through_probes) probes_->draw(frame);
  }

  static void scissor(ivec4 r) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, r.y, r.z - r.x, r.w - r.y);
  }

  // The image of mirror k at recursion depth `level`, made on first use.
  const FrameTarget& imageFor(int level, size_t k, ivec2 size) {
    if (images_.size() <= size_t(level)) images_.resize(size_t(level) + 1);
    auto& row = images_[size_t(level)];
    if (row.size() < planar_.size()) row.resize(planar_.size());
    if (!row[k] || row[k]->size() != size) row[k] = std::make_unique<FrameTarget>(size);
    return *row[k];
  }

  gpu::Program program_, base_program_;
  std::unique_ptr<PlanarProbes> probes_;  // --planar-curved probes
  int not_planar_ = 0;
  std::vector<int> planar_;
  long mirrored_views_ = 0;
  std::vector<std::vector<std::unique_ptr<FrameTarget>>> images_;
};

}  // namespace

MethodEntry planarMethodEntry() {
  MethodEntry entry;
  entry.info.name = "planar";
  entry.info.frame_stats = {"mirrored_views"};
  entry.info.counters = {"cube_captures"};
  entry.info.params = {
      ParamSpec::choice<Curved>(
          "planar-curved", kCurved, Curved::kAuto,
          "planar: what curved reflectors show in its mirrored views: their base colour, or a "
          "probe captured at each (as envmap's); auto: probes in a composite (method mixed), "
          "else the base colour"),
      envmapSizeParam()};
  for (ParamSpec& spec : probeRecaptureParams()) entry.info.params.push_back(std::move(spec));
  entry.info.description =
      "exact planar mirrors by re-rendering the scene from the mirrored eye, the mirror plane as "
      "an oblique near plane, recursing to the reflection order (forward-mapped mirrors paper's "
      "baseline); non-planar reflectors show their base colour";
  entry.create = factoryOf<PlanarMethod>();
  return entry;
}

}  // namespace mirage
