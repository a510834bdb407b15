#include "methods/raytrace/raytrace_method.h"

#include "raytrace/tracer.h"

namespace mirage {

namespace {

class RaytraceMethod final : public Method {
 public:
  explicit RaytraceMethod(const MethodSetup& setup)
      : spp_(setup.params.integer("spp")), tracer_(setup.gpu.scene(), setup.gpu.environmentMap()) {}

  void update(FrameContext& frame) override {
    double ms = tracer_.prepare(frame.gpu.time());
    if (ms > 0.0) {
      last_build_ms_ = ms;
      ++builds_;
    }
  }

  void render(FrameContext& frame) override {
    // Into the kept images: a fresh 7-15 MB image per frame costs page faults (docs/benchmarks.md).
    TraceResult& result = result_;
    tracer_.render(frame.view, {frame.settings.order, spp_}, result);
    // Primary and reflected rays run interleaved per tile; the tracer measured the split.
    if (frame.timer)
      frame.timer->shift(gpu::Part::kDirect, gpu::Part::kReflect, result.stats.reflect_ms);
    frame.target.upload(result.color, result.ids);
    last_ = result.stats;
    primary_rays_ += result.stats.primary_rays;
    reflected_rays_ += result.stats.reflected_rays;
    trace_ms_ += result.stats.ms;
  }

  std::map<std::string, double> stats() const override {
    return {{"bvh_build_ms", last_build_ms_},
            {"bvh_builds", double(builds_)},
            {"primary_rays", double(primary_rays_)},
            {"reflected_rays", double(reflected_rays_)},
            {"trace_ms", trace_ms_},
            {"spp", double(spp_)}};
  }

 private:
  int spp_;
  RayTracer tracer_;
  TraceResult result_;
  TraceStats last_;
  double last_build_ms_ = 0.0, trace_ms_ = 0.0;
  long builds_ = 0;
  uint64_t primary_rays_ = 0, reflected_rays_ = 0;
};

}  // namespace

MethodEntry raytraceMethodEntry() {
  MethodEntry entry;
  entry.info.name = "raytrace";
  entry.info.counters = {"bvh_builds", "primary_rays", "reflected_rays"};
  entry.info.description = "ground truth: Embree traces the full meshes, recursively to order K";
  entry.info.gpu = false;
  entry.info.params = {ParamSpec::integer("spp", 1, 4096, 1,
                                          "ray-tracer samples per pixel (stratified, box filter)")};
  entry.create = factoryOf<RaytraceMethod>();
  return entry;
}

}  // namespace mirage
