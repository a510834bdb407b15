#include "methods/envmap/envmap_method.h"

#include <algorithm>

#include "gpu/buffer.h"
#include "methods/probe_params.h"
#include "render/base_colour.h"
#include "render/cube_capture.h"

namespace mirage {

namespace {

enum class Variant { kProbes, kBox, kInfinite };

std::vector<std::string> shaderDefines(Variant variant) {
  if (variant == Variant::kInfinite) return {"ENVMAP_INFINITE 1"};
  if (variant == Variant::kBox) return {"ENVMAP_BOX 1"};
  return {};
}

class EnvmapMethod final : public Method {
 public:
  EnvmapMethod(const MethodSetup& setup, Variant variant)
      : variant_(variant),
        infinite_(variant == Variant::kInfinite),
        size_(infinite_ ? 0 : setup.params.integer("envmap-size")),
        sphere_proxy_(variant == Variant::kBox &&
                      setup.params.choice<ProbeProxy>("proxy", kProbeProxies) ==
                          ProbeProxy::kSphere),
        program_(gpu::Program::graphics("render/shaders/scene.vert", "methods/envmap/envmap.frag",
                                        shaderDefines(variant))),
        base_program_(baseColourProgram()),
        diffuse_(setup.gpu.scene().diffuseInstances()) {}

  void update(FrameContext& frame) override {
    if (infinite_) return;
    int order = frame.settings.order;
    bool mip = frame.settings.mip;
    // The probes show every diffuse object, the other reflectors and the light.
    std::vector<uint64_t> key = frame.gpu.probeKey(diffuse_);
    if (captured_ && captured_key_ == key && captured_order_ == order && captured_mip_ == mip)
      return;
    capture(frame, order, mip);
    captured_ = true;
    captured_key_ = std::move(key);
    captured_order_ = order;
    captured_mip_ = mip;
  }

  void render(FrameContext& frame) override {
    frame.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    if (frame.settings.order == 0) {
      frame.drawOwnReflectors(base_program_);
      return;
    }
    if (!infinite_) probes_[final_].bind(MIRAGE_UNIT_METHOD);
    if (variant_ == Variant::kBox)
      centres_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_METHOD_SSBO);
    frame.drawOwnReflectors(program_);
  }

  int orderRendered(int requested) const override {
    return infinite_ ? std::min(requested, 1) : requested;
  }

  std::map<std::string, double> stats() const override {
    std::map<std::string, double> s = {{"cube_captures", double(cube_captures_)},
                                       {"capture_passes", double(capture_passes_)}};
    if (variant_ == Variant::kBox) {
      const vec3 e = box_.extent();
      s["proxy_box_x"] = e.x;
      s["proxy_box_y"] = e.y;
      s["proxy_box_z"] = e.z;
    }
    return s;
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
    if (variant_ == Variant::kBox) setUpBox(frame, reflectors);
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

  // The proxy of `envmap-box`: the bounds of the diffuse objects (the room), grown to hold every
  // probe centre, and the probe centres for the shader.
  void setUpBox(FrameContext& frame, const std::vector<int>& reflectors) {
    box_ = Bounds3{};
    for (int i : diffuse_) box_.extend(frame.gpu.instanceBounds(i));
    std::vector<vec4> centres;
    for (int instance : reflectors) {
      vec3 c = frame.gpu.instanceBounds(instance).center();
      centres.push_back(vec4(c, 1.0f));
      box_.extend(c);
    }
    centres_.upload(std::span<const vec4>(centres));
    centres_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_METHOD_SSBO);
    program_.set("u_box_min", box_.lo);
    program_.set("u_box_max", box_.hi);
    program_.set("u_proxy_sphere", sphere_proxy_ ? 1 : 0);
    program_.set("u_sphere", vec4(box_.center(), box_.radius()));
  }

  Variant variant_;
  bool infinite_;
  int size_;
  bool sphere_proxy_;
  gpu::Program program_, base_program_;
  gpu::Texture probes_[2];
  gpu::Buffer centres_;  // envmap-box: vec4 probe centre per reflector
  Bounds3 box_;          // envmap-box: the proxy
  int final_ = 0;
  std::unique_ptr<CubeCapture> cube_;
  bool captured_ = false, captured_mip_ = false;
  std::vector<uint64_t> captured_key_;
  std::vector<int> diffuse_;  // every diffuse instance: what the probes show besides reflectors
  int captured_order_ = -1;
  long cube_captures_ = 0, capture_passes_ = 0;
};

}  // namespace

MethodEntry envmapMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap";
  entry.info.counters = {"cube_captures", "capture_passes"};
  entry.info.description =
      "a cube map captured at each reflector's centre, looked up by direction (reflection probe)";
  entry.info.params = {envmapSizeParam()};
  entry.create = factoryOf<EnvmapMethod>(Variant::kProbes);
  return entry;
}

MethodEntry envmapBoxMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap-box";
  entry.info.counters = {"cube_captures", "capture_passes"};
  entry.info.description =
      "the reflection probes looked up through a box proxy of the room (parallax-corrected cube "
      "map)";
  entry.info.params = {envmapSizeParam(), probeProxyParam()};
  entry.create = factoryOf<EnvmapMethod>(Variant::kBox);
  return entry;
}

MethodEntry envmapInfiniteMethodEntry() {
  MethodEntry entry;
  entry.info.name = "envmap-infinite";
  entry.info.description = "the scene's distant environment only (light probe at infinity)";
  entry.info.max_order = 1;
  entry.create = factoryOf<EnvmapMethod>(Variant::kInfinite);
  return entry;
}

}  // namespace mirage
