#include "methods/none/none_method.h"

#include "render/base_colour.h"

namespace mirage {

namespace {

class NoneMethod final : public Method {
 public:
  explicit NoneMethod(const MethodSetup&) : program_(baseColourProgram()) {}

  void update(FrameContext&) override {}
  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    frame.drawOwnReflectors(program_);
  }

 private:
  gpu::Program program_;
};

}  // namespace

MethodEntry noneMethodEntry() {
  MethodEntry entry;
  entry.info.name = "none";
  entry.info.description = "no reflections: reflectors shaded with their base colour";
  entry.info.max_order = 0;
  entry.create = factoryOf<NoneMethod>();
  return entry;
}

}  // namespace mirage
