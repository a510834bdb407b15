#include "methods/envmap/envmap_method.h"

#include <algorithm>

#include "render/cube_capture.h"

namespace mirage {

namespace {

class EnvmapMethod final : public Method {
 public:
  EnvmapMethod(const MethodSetup& setup, bool infinite)
      : info_(setup.info),
        infinite_(infinite),
        size_(infinite ? 0 : setup.params.integer("envmap-size")),
        program_(gpu::Program::graphics(
            "render/shaders/scene.vert", "methods/envmap/envmap.frag",
            infinite ? std::vector<std::string>{"ENVMAP_INFINITE 1"} : std::vector<std::string>{})),
        base_program_(
            gpu::Program::graphics("render/shaders/scene.vert", "methods/none/none.frag")) {}

  const MethodInfo& info() const override { return info_; }

  void update(FrameContext& frame) override {
    if (infinite_) return;
    int order = frame.settings.order;
    bool mip = frame.settings.mip;
    if (captured_ && captured_version_ == frame.gpu.version() && captured_order_ == order &&
        captured_mip_ == mip)
      return;
    capture(frame, order, mip);
    captured_ = true;
    captured_version_ = frame.gpu.version();
    captured_order_ = order;
    captured_mip_ = mip;
  }

  void render(FrameContext& frame) override {
    frame.passes.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    if (frame.settings.order == 0) {
      frame.passes.drawReflectors(base_program_);
      return;
    }
    if (!infinite_) probes_[final_].bind(MIRAGE_UNIT_METHOD);
    frame.passes.drawReflectors(program_);
  }

  int orderRendered(int requested) const override {
    return infinite_ ? std::min(requested, 1) : requested;
  }

  std::map<std::string, double> stats() const override {
    return {{"cube_captures", double(cube_captures_)}, {"capture_passes", double(capture_passes_)}};
  }

 private:
  // Renders every reflector's probe; with several reflectors and order K, K passes, each
  // showing the other reflectors with the probes of the pass before.
  void capture(FrameContext& frame, int order, bool mip) {
    const Scene& scene = frame.gpu.scene();
    std::vector<int> reflectors = scene.reflectorInstances();
    if (reflectors.empty() || order == 0) return;
    int levels = mip ? gpu::Texture::fullMipLevels(size_) : 1;
    for (auto& probe : probes_)
      if (probe.layers() != 6 * int(reflectors.size()) || probe.levels() != levels)
        probe = gpu::Texture::createCubeArray(GL_RGBA16F, size_, int(reflectors.size()), levels);
    if (!cube_) cube_ = std::make_unique<CubeCapture>(size_);

    Bounds3 bounds = scene.bounds(frame.gpu.time());
    float radius = std::max(bounds.radius(), 1e-3f);
    float near_plane = 1e-3f * radius, far_plane = 100.0f * radius;
    int passes = reflectors.size() > 1 ? order : 1;
    for (int pass = 0; pass < passes; ++pass) {
      int write = pass % 2, read = 1 - write;
      const gpu::Program& others = pass == 0 ? base_program_ : program_;
      if (pass > 0) probes_[read].bind(MIRAGE_UNIT_METHOD);
      for (size_t r = 0; r < reflectors.size(); ++r) {
        int instance = reflectors[r];
        vec3 center = frame.gpu.instanceBounds(instance).center();
        cube_->capture(probes_[write], int(r), center, near_plane, far_plane, [&](const View& v) {
          frame.passes.begin(v, frame.settings);
          frame.passes.drawDirect();
          frame.passes.drawReflectors(others, instance);
        });
        ++cube_captures_;
      }
      if (mip) probes_[write].generateMipmaps();
      final_ = write;
      ++capture_passes_;
    }
  }

  const MethodInfo& info_;
  bool infinite_;
  int size_;
  gpu::Program program_, base_program_;
  gpu::Texture probes_[2];
  int final_ = 0;
  std::unique_ptr<CubeCapture> cube_;
  bool captured_ = false, captured_mip_ = false;
  uint64_t captured_version_ = 0;
  int captured_order_ = -1;
  long cube_captures_ = 0, capture_passes_ = 0;
};

}  // namespace

MethodEntry envmapMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap";
  entry.info.description =
      "a cube map captured at each reflector's centre, looked up by direction (reflection probe)";
  entry.info.params = {ParamSpec::integer("envmap-size", 8, 2048, 256,
                                          "face size of each reflector's cube map, in texels")};
  entry.create = [](const MethodSetup& setup) -> std::unique_ptr<Method> {
    return std::make_unique<EnvmapMethod>(setup, false);
  };
  return entry;
}

MethodEntry envmapInfiniteMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap-infinite";
  entry.info.description = "the scene's distant environment only (light probe at infinity)";
  entry.info.max_order = 1;
  entry.create = [](const MethodSetup& setup) -> std::unique_ptr<Method> {
    return std::make_unique<EnvmapMethod>(setup, true);
  };
  return entry;
}

}  // namespace mirage
