#include "methods/none/none_method.h"

#include "render/base_colour.h"

namespace mirage {

namespace {

class NoneMethod final : public Method {
 public:
  explicit NoneMethod(const MethodInfo& info) : info_(info), program_(baseColourProgram()) {}

  const MethodInfo& info() const override { return info_; }
  void update(FrameContext&) override {}
  void render(FrameContext& frame) override {
    frame.passes.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    frame.passes.drawReflectors(program_);
  }

 private:
  const MethodInfo& info_;
  gpu::Program program_;
};

}  // namespace

MethodEntry noneMethodEntry() {
  MethodEntry entry;
  entry.info.name = "none";
  entry.info.description = "no reflections: reflectors shaded with their base colour";
  entry.info.max_order = 0;
  entry.create = [](const MethodSetup& setup) -> std::unique_ptr<Method> {
    return std::make_unique<NoneMethod>(setup.info);
  };
  return entry;
}

}  // namespace mirage
