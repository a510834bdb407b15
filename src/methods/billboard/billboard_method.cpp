#include "methods/billboard/billboard_method.h"

#include "methods/impostor/billboard_stage.h"
#include "render/base_colour.h"

namespace mirage {

namespace {

class BillboardMethod final : public Method {
 public:
  explicit BillboardMethod(const MethodSetup& setup)
      : stage_(billboardStageOptions(setup.params), setup.gpu.scene()),
        last_bounce_reflective_(lastBounceReflective(setup.params)),
        shader_("methods/billboard/billboard.frag", stage_.shaderDefines(),
                impostorPass(setup.params)),
        base_program_(baseColourProgram()) {}

  void update(FrameContext& frame) override { stage_.update(frame); }

  void render(FrameContext& frame) override {
    passes_ = {};
    if (!stage_.beginFrame(frame, shader_, base_program_, last_bounce_reflective_)) return;
    passes_ = shader_.draw(frame, gbuffer_);
  }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> s = stage_.stats();
    addPassStats(s, passes_);
    return s;
  }

 private:
  BillboardStage stage_;
  bool last_bounce_reflective_;
  ImpostorShader shader_;
  gpu::Program base_program_;
  ReflectorGBuffer gbuffer_;
  ReflectorPasses passes_;  // the last frame's
};

}  // namespace

MethodEntry billboardMethodEntry() {
  MethodEntry entry;
  entry.info.name = "billboard";
  entry.info.description =
      "billboard impostors: diffuse and reflective billboards to order K (impostor paper, §3)";
  entry.info.min_order = 1;
  entry.info.params = billboardStageParams();
  entry.info.counters = {"billboard_captures", "environment_captures"};
  entry.info.frame_stats = BillboardStage::frameStats();
  entry.create = factoryOf<BillboardMethod>();
  return entry;
}

}  // namespace mirage
