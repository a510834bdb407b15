#include "methods/billboard/billboard_method.h"

#include <span>

#include "gpu/buffer.h"
#include "methods/billboard/billboard_capture.h"
#include "methods/billboard/billboard_set.h"
#include "render/cube_capture.h"

namespace mirage {

namespace {

class BillboardMethod final : public Method {
 public:
  explicit BillboardMethod(const MethodSetup& setup)
      : info_(setup.info),
        options_{float(setup.params.real("billboard-fov")),
                 setup.params.text("billboard-objects") == "all",
                 float(setup.params.real("morph-height"))},
        last_bounce_reflective_(setup.params.text("last-bounce") == "all"),
        env_size_(setup.params.integer("envmap-size")),
        capture_(setup.params.integer("billboard-size")),
        program_(gpu::Program::graphics("render/shaders/scene.vert",
                                        "methods/billboard/billboard.frag")),
        base_program_(
            gpu::Program::graphics("render/shaders/scene.vert", "methods/none/none.frag")) {}

  const MethodInfo& info() const override { return info_; }

  void update(FrameContext& frame) override {
    GpuScene& gpu = frame.gpu;
    // Placements and captures depend on the scene's state only (its version) and on the mip
    // setting; a frame that changes neither (a camera move) has nothing to redo.
    if (updated_ && updated_version_ == gpu.version() && updated_mip_ == frame.settings.mip) {
      last_captures_ = 0;
      return;
    }
    const Scene& scene = gpu.scene();
    set_ = placeBillboards(scene, gpu.time(), options_);
    std::vector<shading::BillboardData> data = set_.gpuData(scene);
    billboards_.upload(std::span<const shading::BillboardData>(data));
    ranges_.upload(std::span<const shading::BillboardRange>(set_.ranges));
    entries_.upload(std::span<const int>(set_.entries));
    last_captures_ = capture_.update(gpu, frame.passes, set_, frame.settings);
    updateEnvironment(frame);
    updated_ = true;
    updated_version_ = gpu.version();
    updated_mip_ = frame.settings.mip;
  }

  void render(FrameContext& frame) override {
    frame.passes.drawDirect();
    frame.beginPart(gpu::Part::kReflect);
    if (frame.settings.order == 0 || set_.ranges.empty()) {
      frame.passes.drawReflectors(base_program_);
      return;
    }
    billboards_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARDS);
    ranges_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARD_RANGES);
    entries_.bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_BILLBOARD_ENTRIES);
    capture_.surfaces().bind(MIRAGE_UNIT_BILLBOARD_SURFACE);
    capture_.positions().bind(MIRAGE_UNIT_BILLBOARD_POSITION);
    const bool captured_env = !set_.environmentInstances().empty();
    (captured_env ? environment_ : frame.gpu.environment()).bind(MIRAGE_UNIT_BILLBOARD_ENV);
    program_.set("u_ground", set_.ground);
    program_.set("u_last_bounce_reflective", last_bounce_reflective_ ? 1 : 0);
    if (set_.ground >= 0) {
      program_.set("u_morph_min", set_.morph_box.lo);
      program_.set("u_morph_max", set_.morph_box.hi);
      program_.set("u_morph_centre", set_.environment_centre);
    }
    // Depth first, then the expensive shader once per visible pixel (no overdraw).
    glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    frame.passes.drawReflectors(base_program_);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    frame.passes.drawReflectors(program_);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
  }

  std::map<std::string, double> stats() const override {
    int diffuse = 0, reflective = 0;
    for (const BillboardSpec& b : set_.billboards)
      (b.kind == BillboardSpec::Kind::kReflective ? reflective : diffuse)++;
    return {{"billboard_captures", double(capture_.captures())},
            {"billboard_captures_last_update", double(last_captures_)},
            {"diffuse_billboards", double(diffuse)},
            {"reflective_billboards", double(reflective)},
            {"environment_captures", double(env_captures_)}};
  }

 private:
  // Diffuse objects without billboards (and the ground, when it morphs into the environment)
  // are reflected through a cube map captured at the reflectors' centroid E, with the distant
  // environment; re-captured when the scene changes.
  void updateEnvironment(FrameContext& frame) {
    const std::vector<int> instances = set_.environmentInstances();
    if (instances.empty()) return;
    GpuScene& gpu = frame.gpu;
    if (env_valid_ && env_version_ == gpu.version()) return;
    const Scene& scene = gpu.scene();
    const vec3 centre = set_.environment_centre;
    const int levels = frame.settings.mip ? gpu::Texture::fullMipLevels(env_size_) : 1;
    if (environment_.levels() != levels)
      environment_ = gpu::Texture::createCube(GL_RGBA16F, env_size_, levels);
    if (!cube_) cube_ = std::make_unique<CubeCapture>(env_size_);
    const float radius = std::max(scene.bounds(gpu.time()).radius(), 1e-3f);
    cube_->capture(environment_, 0, centre, 1e-3f * radius, 100.0f * radius, [&](const View& v) {
      frame.passes.begin(v, frame.settings);
      frame.passes.drawBackground();
      frame.passes.drawDiffuseInstances(instances);
    });
    if (levels > 1) environment_.generateMipmaps();
    env_valid_ = true;
    env_version_ = gpu.version();
    ++env_captures_;
  }

  const MethodInfo& info_;
  BillboardSetOptions options_;
  bool last_bounce_reflective_;
  int env_size_;
  BillboardCapture capture_;
  gpu::Program program_, base_program_;
  BillboardSet set_;
  gpu::Buffer billboards_, ranges_, entries_;
  gpu::Texture environment_;
  std::unique_ptr<CubeCapture> cube_;
  bool env_valid_ = false;
  uint64_t env_version_ = 0;
  long env_captures_ = 0;
  int last_captures_ = 0;
  bool updated_ = false, updated_mip_ = false;
  uint64_t updated_version_ = 0;
};

}  // namespace

MethodEntry billboardMethodEntry() {
  MethodEntry entry;
  entry.info.name = "billboard";
  entry.info.description =
      "billboard impostors: diffuse and reflective billboards to order K (impostor paper, §3)";
  entry.info.min_order = 1;
  entry.info.params = {
      ParamSpec::integer("billboard-size", 16, 4096, 256,
                         "face size of each billboard texture, in texels"),
      ParamSpec::real("billboard-fov", 1.0, 60.0, 10.0,
                      "field of view of the billboard capture camera, in degrees"),
      ParamSpec::choice("billboard-objects", {"all", "planar"}, "all",
                        "which diffuse objects get billboards: all, or planar ones only (the "
                        "others are reflected through a captured environment map)"),
      ParamSpec::choice("last-bounce", {"all", "diffuse"}, "all",
                        "what the last bounce tests: all billboards (a reflector hit shows its "
                        "base colour, as the ray tracer at order K) or diffuse ones only (the "
                        "paper's D + R - 1 + D count)"),
      ParamSpec::real("morph-height", 0.0, 1.0e6, 0.0,
                      "height of the transition walls that morph the ground billboard into the "
                      "environment (scene units; 0 = off)"),
      ParamSpec::integer("envmap-size", 8, 2048, 256,
                         "face size of each reflector's cube map, in texels")};
  entry.create = [](const MethodSetup& setup) -> std::unique_ptr<Method> {
    return std::make_unique<BillboardMethod>(setup);
  };
  return entry;
}

}  // namespace mirage
