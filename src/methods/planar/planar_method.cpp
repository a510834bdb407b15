#include "methods/planar/planar_method.h"

#include <memory>

#include "render/base_colour.h"
#include "render/mirror_images.h"

namespace mirage {

namespace {

class PlanarMethod final : public Method {
 public:
  explicit PlanarMethod(const MethodSetup& setup)
      : program_(gpu::Program::graphics("render/shaders/scene.vert",
                                        "render/shaders/mirror_image.frag")),
        base_program_(baseColourProgram()),
        planar_(planarReflectors(setup.gpu.scene(), &not_planar_, "planar")) {}

  void update(FrameContext&) override {}  // nothing captured: every frame is drawn anew

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
            {"mirrored_views", double(mirrored_views_)}};
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
    // view shows only this method's own reflectors.
    drawMirrorImages(frame.gpu, shown, program_, base_program_, from,
                     level == 0 ? frame.own : nullptr);
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
  entry.info.description =
      "exact planar mirrors by re-rendering the scene from the mirrored eye, the mirror plane as "
      "an oblique near plane, recursing to the reflection order (forward-mapped mirrors paper's "
      "baseline); non-planar reflectors show their base colour";
  entry.create = factoryOf<PlanarMethod>();
  return entry;
}

}  // namespace mirage
