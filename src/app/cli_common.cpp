#include "app/cli_common.h"

#include <filesystem>
#include <fstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "core/memory_cap.h"
#include "core/supersample.h"
#include "gpu/framebuffer.h"
#include "methods/assignment.h"
#include "methods/method.h"
#include "scene/camera_file.h"

namespace mirage::app {

void addSceneOptions(CLI::App* app, SceneArgs& args) {
  app->add_option("--scene", args.scene,
                  "built-in or asset scene name (see `mirage scenes`), a .json scene file, or a "
                  "mesh file (.ply, .ply.gz, .obj, .gltf, .glb, ...)")
      ->required();
  app->add_option("--reflectors", args.reflectors,
                  "spheres9, plaza: keep the first N reflectors (1..9, 1..32)");
  app->add_option("--objects", args.objects, "plaza: lay out N diffuse objects (10..1000)");
  app->add_option("--camera", args.camera, "the scene camera to use (default: the first)");
  app->add_option("--camera-path", args.camera_path,
                  "a camera file (one camera of the scene format: still, or a path of keys, as "
                  "`mirage view` records them) to use instead of the scene's cameras");
  args.time_option =
      app->add_option("--time", args.time, "scene time in seconds (animated scenes, camera paths)");
  app->add_option("--stage", args.stage,
                  "model files: auto (a file with a camera of its own is shown as it is, one "
                  "without on the default stage), on (the default stage, the file's cameras "
                  "fitted along) or off (as it is, framed when it has no camera)");
  addDefaulted(app, "--max-memory", args.max_memory,
               "what one input file (mesh, image, compressed stream) may make mirage allocate, "
               "checked from its header before reading (1M..1T, e.g. 512M, 4G)");
}

void addFrameOptions(CLI::App* app, FrameArgs& args) {
  args.size_option = addDefaulted(app, "--size", args.size,
                                  "image size WxH (1..16384 each); not given, the height "
                                  "follows the camera's aspect ratio when it has one");
  addDefaulted(app, "--order", args.order,
               fmt::format("reflection order K (0..{}; 0 = no reflections)", kMaxOrder));
  addDefaulted(app, "--mip", args.mip, "mip-mapped reflection lookups: on|off");
  addDefaulted(app, "--exposure", args.exposure, "exposure multiplier before tone mapping (> 0)");
  addDefaulted(app, "--tonemap", args.tonemap, "tone map: clamp|reinhard|aces");
}

void addSsaaOption(CLI::App* app, FrameArgs& args) {
  addDefaulted(app, "--ssaa", args.ssaa,
               "supersampling: render N x N sub-pixels per output pixel and box-filter them "
               "in linear radiance; the ray tracer traces the same sub-pixel positions (1..8)");
}

void addMethodParamOptions(CLI::App* app, std::map<std::string, std::string>& values) {
  for (const ParamSpec& spec : allMethodParams()) {
    std::string name = spec.name;
    app->add_option_function<std::string>(
           "--" + name, [&values, name](const std::string& v) { values[name] = v; },
           spec.help + " (" + spec.rangeText() +
               (spec.default_value.empty() ? "" : ", default " + spec.default_value) + ")")
        ->group("Method parameters");
  }
}

ivec2 parseSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
    throwInput("--size {}: expected WxH, e.g. 720x512", text);
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throwInput("--size {}: each side must be in 1..16384", text);
  return {w, h};
}

ivec2 imageSize(const FrameArgs& args, const CameraDesc& camera) {
  ivec2 size = parseSize(args.size);
  if (!(camera.aspect > 0.0f)) return size;
  const int height = int(std::clamp(std::lround(float(size.x) / camera.aspect), 1L, 16384L));
  if (args.size_option && args.size_option->count() > 0) {
    if (height != size.y)
      spdlog::info(
          "--size {}x{}: camera '{}' was made for {}x{} (aspect {}); its vertical field of view "
          "is kept",
          size.x, size.y, camera.name, size.x, height, camera.aspect);
    return size;
  }
  return {size.x, height};
}

Scene loadSceneFromArgs(SceneArgs& args) {
  if (!(args.time >= 0.0f && args.time <= 1e6f))
    throwInput("--time {}: allowed 0..1e6 seconds", args.time);
  if (!args.camera_path.empty() && !args.camera.empty())
    throwInput("--camera {} and --camera-path {}: give one of them", args.camera, args.camera_path);
  setMaxMemory(parseByteSize("--max-memory", args.max_memory));
  SceneOptions options;
  options.reflectors = args.reflectors;
  options.objects = args.objects;
  if (!args.stage.empty()) {
    options.stage = findChoice<StageMode>(kStageModes, args.stage);
    if (!options.stage)
      throwInput("--stage {}: allowed {}", args.stage, choiceNames<StageMode>(kStageModes, "|"));
  }
  Scene scene = loadScene(args.scene, options);
  if (!args.camera_path.empty()) {
    const CameraFile file = loadCameraFile(args.camera_path);
    scene.cameras.insert(scene.cameras.begin(), file.camera);
    if (file.time && !(args.time_option && args.time_option->count() > 0)) args.time = *file.time;
  }
  // A scene file's assignment is checked as the scene is loaded, whatever the method.
  if (!scene.reflections.empty()) resolveAssignment(scene, scene.reflections);
  return scene;
}

FrameSettings frameSettings(const FrameArgs& args) {
  if (args.order < 0 || args.order > kMaxOrder)
    throwInput("--order {}: allowed 0..{}", args.order, kMaxOrder);
  if (args.mip != "on" && args.mip != "off") throwInput("--mip {}: allowed on|off", args.mip);
  if (args.ssaa < 1 || args.ssaa > kMaxSsaa)
    throwInput("--ssaa {}: allowed 1..{} (sub-pixels per output pixel along each axis)", args.ssaa,
               kMaxSsaa);
  FrameSettings s;
  s.order = args.order;
  s.mip = args.mip == "on";
  s.pixel_scale = args.ssaa;
  return s;
}

ivec2 supersampledFrameSize(ivec2 size, int ssaa) {
  const ivec2 frame = supersampledSize(size, ssaa);
  if (ssaa == 1) return frame;
  const int largest = gpu::maxFrameSide();
  if (std::max(frame.x, frame.y) > largest)
    throwInput(
        "--ssaa {} with --size {}x{}: the frame would be {}x{}, beyond this driver's largest "
        "frame side {} (use a smaller --ssaa or --size)",
        ssaa, size.x, size.y, frame.x, frame.y, largest);
  // The frame target (RGBA32F colour, R32UI ids, depth), its read-back, and the frame-sized
  // buffers a method keeps (G-buffers, splat and zexel words, mirror images): 64 bytes a pixel
  // bounds them all.
  constexpr uint64_t kBytesPerPixel = 64;
  const uint64_t bytes = saturatingMul(uint64_t(frame.x) * uint64_t(frame.y), kBytesPerPixel);
  if (bytes > maxMemory())
    throwInput(
        "--ssaa {} with --size {}x{}: a {}x{} frame needs about {}; --max-memory allows {} (use "
        "a smaller --ssaa or --size, or raise --max-memory)",
        ssaa, size.x, size.y, frame.x, frame.y, formatBytes(bytes), formatBytes(maxMemory()));
  return frame;
}

DisplaySettings displaySettings(const FrameArgs& args) {
  if (!(args.exposure > 0.0f) || !std::isfinite(args.exposure))
    throwInput("--exposure {}: must be a finite number > 0", args.exposure);
  return {args.exposure, parseToneMap(args.tonemap)};
}

std::unique_ptr<gpu::Context> openHeadlessContext() {
  gpu::ContextOptions options;
  options.debug = gpu::debugContextByDefault();
  return gpu::createHeadlessContext(options);
}

void warnUnusedParams(const std::map<std::string, std::string>& values,
                      const std::vector<std::string>& methods) {
  for (const auto& [name, value] : values) {
    bool used = false;
    for (const std::string& m : methods)
      for (const ParamSpec& spec : findMethod(m).info.params) used = used || spec.name == name;
    if (!used)
      spdlog::warn("--{} {} is ignored: none of the selected methods uses it", name, value);
  }
}

std::string cpuDescription() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  return fmt::format("{} ({} threads)", model, std::thread::hardware_concurrency());
}

void ensureDirectory(const std::string& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec || !std::filesystem::is_directory(path))
    throwInput("-o {}: cannot create the output directory ({})", path,
               ec ? ec.message() : "a file of that name exists");
}

}  // namespace mirage::app
