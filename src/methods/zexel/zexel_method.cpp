#include "methods/zexel/zexel_method.h"

#include <algorithm>
#include <memory>

#include "methods/zexel/zexel_camera.h"
#include "methods/zexel/zexel_curved.h"
#include "render/mirror_images.h"

namespace mirage {

namespace {

// One mirror's depth-preserving reflection map.
struct ZexelMap {
  int mirror = -1;
  std::unique_ptr<FrameTarget> zexels;  // rgb; alpha: distance along the ray (the frame's)
  View reference;
  vec3 normal{0.0f};                    // the side it was captured for
  std::unique_ptr<FrameTarget> warped;  // this frame's image from the mirrored eye
};

class ZexelMethod final : public Method {
 public:
  explicit ZexelMethod(const MethodSetup& setup)
      : info_(setup.info),
        size_(setup.params.integer("zexel-size")),
        splat_(setup.params.integer("zexel-splat")),
        fov_(float(setup.params.real("zexel-fov"))),
        warp_program_(gpu::Program::graphics("methods/zexel/zexel_warp.vert",
                                             "methods/zexel/zexel_warp.frag")),
        mirror_program_(gpu::Program::graphics("render/shaders/scene.vert",
                                               "render/shaders/mirror_image.frag")),
        base_program_(
            gpu::Program::graphics("render/shaders/scene.vert", "methods/none/none.frag")),
        empty_vao_(gpu::createVertexArray()),
        curved_(setup) {
    for (int mirror : planarReflectors(setup.gpu.scene(), &not_planar_))
      maps_.push_back(ZexelMap{mirror, nullptr, View(), vec3(0.0f), nullptr});
  }

  const MethodInfo& info() const override { return info_; }

  // Captures every map the first time, when the scene changed, or when the eye crossed to a
  // mirror's other side.
  void update(FrameContext& frame) override {
    curved_.update(frame);
    const bool changed = captured_version_ != frame.gpu.version() || !captured_;
    for (ZexelMap& map : maps_) {
      vec3 point, normal;
      if (!plane(frame, map.mirror, frame.view.eye(), point, normal)) continue;
      if (!changed && map.zexels && glm::dot(normal, map.normal) > 0.0f) continue;
      capture(frame, map, point, normal);
    }
    captured_ = true;
    captured_version_ = frame.gpu.version();
  }

  void render(FrameContext& frame) override {
    frame.passes.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    zexels_warped_ = 0;
    std::vector<MirrorImage> shown;
    if (frame.settings.order > 0)
      for (ZexelMap& map : maps_)
        if (warp(frame, map)) shown.push_back({map.mirror, map.warped.get()});
    frame.target.bind();
    frame.passes.begin(frame.view, frame.settings);
    curved_.draw(frame);
    drawMirrorImages(frame.gpu, shown, mirror_program_, base_program_);
  }

  int orderRendered(int requested) const override { return std::min(requested, 1); }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> s = {{"zexel_maps", double(maps_.size())},
                                       {"zexel_captures", double(captures_)},
                                       {"zexels_warped", double(zexels_warped_)},
                                       {"reflectors_not_planar", double(not_planar_)}};
    curved_.addStats(s);
    return s;
  }

 private:
  static bool plane(FrameContext& frame, int mirror, const vec3& eye, vec3& point, vec3& normal) {
    return planarInstancePlane(frame.gpu.scene(), mirror,
                               frame.gpu.instanceMatrices()[size_t(mirror)], eye, point, normal);
  }

  // The map of one mirror: the scene in front of it from the reference camera behind it, the
  // other reflectors in their base colour (one bounce).
  void capture(FrameContext& frame, ZexelMap& map, const vec3& point, const vec3& normal) {
    const Bounds3 b = frame.gpu.instanceBounds(map.mirror);
    const float half_diagonal = std::max(0.5f * glm::length(b.extent()), 1e-4f);
    map.reference = zexelReferenceView(point, normal, half_diagonal, size_, fov_);
    map.normal = normal;
    if (!map.zexels || map.zexels->size() != ivec2(size_))
      map.zexels = std::make_unique<FrameTarget>(ivec2(size_));
    map.zexels->bind();
    map.zexels->clear();
    frame.passes.begin(map.reference, frame.settings);
    frame.passes.drawDirect();
    frame.passes.drawReflectors(base_program_, map.mirror);
    ++captures_;
  }

  // Warps a mirror's zexels into the image seen from the eye mirrored in it; false when the
  // mirror is edge-on or the eye is on the other side than the map's.
  bool warp(FrameContext& frame, ZexelMap& map) {
    vec3 point, normal;
    if (!map.zexels || !plane(frame, map.mirror, frame.view.eye(), point, normal) ||
        glm::dot(normal, map.normal) <= 0.0f)
      return false;
    const View mirrored = frame.view.mirrored(point, normal);
    const ivec2 size = frame.view.size();
    if (!map.warped || map.warped->size() != size) map.warped = std::make_unique<FrameTarget>(size);
    map.warped->bind();
    map.warped->clear();
    frame.passes.begin(mirrored, frame.settings);
    frame.passes.drawBackground();
    const View& ref = map.reference;
    warp_program_.set("u_pi", mat4(zexelPixelMatrix(ref, ref.nearPlane())));
    warp_program_.set("u_po_inverse",
                      mat4(glm::inverse(zexelPixelMatrix(mirrored, mirrored.nearPlane()))));
    warp_program_.set("u_ci", ref.eye());
    warp_program_.set("u_co", mirrored.eye());
    warp_program_.set("u_near_far_o", vec2(mirrored.nearPlane(), mirrored.farPlane()));
    warp_program_.set("u_width", size_);
    warp_program_.set("u_splat", float(splat_));
    map.zexels->color().bind(MIRAGE_UNIT_METHOD);
    warp_program_.use();
    glEnable(GL_PROGRAM_POINT_SIZE);
    glBindVertexArray(empty_vao_.id());
    glDrawArrays(GL_POINTS, 0, size_ * size_);
    glDisable(GL_PROGRAM_POINT_SIZE);
    zexels_warped_ += long(size_) * size_;
    return true;
  }

  const MethodInfo& info_;
  int size_, splat_;
  float fov_;
  gpu::Program warp_program_, mirror_program_, base_program_;
  gpu::Handle<gpu::VertexArrayTraits> empty_vao_;
  std::vector<ZexelMap> maps_;
  int not_planar_ = 0;
  bool captured_ = false;
  uint64_t captured_version_ = 0;
  long captures_ = 0, zexels_warped_ = 0;
  ZexelCurvedReflectors curved_;  // the non-planar reflectors, by inverse warping
};

}  // namespace

MethodEntry zexelMethodEntry() {
  MethodEntry entry;
  entry.info.name = "zexel";
  entry.info.description =
      "depth-preserving reflection maps: per planar mirror a map of colour and distance from a "
      "reference camera behind it, forward-warped (McMillan) to the mirrored eye each frame and "
      "splatted (forward-mapped planar mirror paper); non-planar reflectors inverse-warp a cube "
      "map of colour and distance";
  entry.info.max_order = 1;
  entry.info.params = {
      ParamSpec::integer("zexel-size", 16, 4096, 512,
                         "side of each mirror's depth-preserving reflection map, in zexels"),
      ParamSpec::integer("zexel-splat", 1, 9, 3,
                         "side of the square splat of a warped zexel, in pixels (the paper: 3)"),
      ParamSpec::real("zexel-fov", 10.0, 170.0, 100.0,
                      "vertical field of view of the reference camera behind each mirror, in "
                      "degrees")};
  for (const ParamSpec& p : ZexelCurvedReflectors::params()) entry.info.params.push_back(p);
  entry.create = [](const MethodSetup& setup) -> std::unique_ptr<Method> {
    return std::make_unique<ZexelMethod>(setup);
  };
  return entry;
}

}  // namespace mirage
