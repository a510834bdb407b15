// `mirage compare`: every chosen method against a reference (the ray tracer unless --reference
// names another method) on one view, or on the frames along a camera path (--path-frames):
// images, absolute-error and FLIP maps, PSNR/SSIM/FLIP (all pixels and reflector pixels) and
// times, as DIR/index.html and DIR/metrics.json.
#include <spdlog/spdlog.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/compare_analysis.h"
#include "app/compare_common.h"
#include "core/error.h"
#include "eval/flip.h"
#include "eval/heatmap.h"

namespace mirage::app {

namespace {

struct CompareArgs : RenderingArgs {
  std::string methods = "all";
  std::string reference = "raytrace";
  int path_frames = 0;
  std::string reference_check = "auto";
  int reference_spp = 64;
  std::string output;
  float heatmap_max = 0.25f;
  const CLI::Option* time_option = nullptr;  // to tell a given --time from the default
};

// The frame count a path may be sampled at: enough for a minute at 60 Hz and then some.
constexpr int kMaxPathFrames = 100000;

struct Rendered {
  RenderedFrame frame;
  double first_ms = 0.0, ms = 0.0;
};

// Renders two frames: the first includes captures and builds, the second is a steady frame.
Rendered renderTwice(FrameRenderer& renderer, Method& method, const View& view, float time,
                     const FrameSettings& settings, gpu::Clock clock) {
  Rendered r;
  for (int i = 0; i < 2; ++i) {
    gpu::FrameTimer timer(clock);
    renderer.render(method, view, time, settings, &timer);
    double ms = timer.takeResults().front().total_ms;
    (i == 0 ? r.first_ms : r.ms) = ms;
  }
  r.frame = renderer.read();
  return r;
}

// The reference's side of the view: its image and mask, the causes of its reflector pixels (the
// cause image written) and, when asked, its distance from a converged image.
ReferenceFrame referenceFrame(CompareRun& run, const Image& shown, const IdImage& mask,
                              const View& view, const View& frame_view, float time, int check_spp) {
  ReferenceFrame reference{shown, mask, std::nullopt};
  reference.causes = traceCauses(run, frame_view, time, mask);
  run.report.cause_image = "causes.png";
  writePng((run.dir / run.report.cause_image).string(), causeImage(*reference.causes, shown));
  if (check_spp > 0) checkReference(run, view, time, reference, check_spp);
  return reference;
}

// The single view: each method renders it twice (a first and a steady frame) at the frame size;
// under --ssaa the times come from the same two frames of a fresh method at the output size.
void compareView(CompareRun& run, const View& view, const View& frame_view, float time,
                 int check_spp) {
  ReferenceFrame reference;
  for (const std::string& name : run.methods) {
    auto method = run.renderer->createMethod(name, run.params, run.settings);
    Rendered r = renderTwice(*run.renderer, *method, frame_view, time, run.settings,
                             methodClock(run, *method));
    const RenderedFrame frame = downsample(std::move(r.frame), run.ssaa);
    Image shown = toDisplay(frame.color, run.display);
    if (name == run.methods.front())
      reference = referenceFrame(run, shown, frame.ids, view, frame_view, time, check_spp);
    MethodReport m = describeMethod(run, name, *method);
    Image2D<float> flip;
    m.metrics = analyseFrame(run, shown, reference, m.regions, &flip);
    if (run.timing_renderer) {
      method.reset();  // the supersampled method's GPU memory, before the native one's
      FrameSettings native = run.settings;
      native.pixel_scale = 1;
      auto timed = run.timing_renderer->createMethod(name, run.params, native);
      r = renderTwice(*run.timing_renderer, *timed, view, time, native, methodClock(run, *timed));
    }
    m.ms = r.ms;
    m.first_ms = r.first_ms;
    MapFiles files = writeMaps(run, name, shown, reference.display, flip);
    m.image = files.image;
    m.error_image = files.error_image;
    m.flip_image = files.flip_image;
    spdlog::info(
        "{:>16}: PSNR {:6.2f} dB (reflector {:6.2f}), SSIM {:.4f}, FLIP {:.4f} (reflector {:.4f}), "
        "{:8.2f} ms",
        name, m.metrics.psnr, m.metrics.psnr_reflector, m.metrics.ssim, m.metrics.flip,
        m.metrics.flip_reflector, m.ms);
    run.report.methods.push_back(std::move(m));
  }
}

// The camera --path-frames samples: the chosen one, which must have a path.
const CameraDesc& pathCamera(const Scene& scene, const CompareArgs& args) {
  const CameraDesc& camera = scene.camera(args.scene.camera);
  if (camera.path.empty()) {
    std::string with_path;
    for (const CameraDesc& c : scene.cameras)
      if (!c.path.empty()) with_path += (with_path.empty() ? "" : ", ") + c.name;
    throwInput(
        "--path-frames {}: camera '{}' of scene '{}' has no path ({}; pick one with --camera)",
        args.path_frames, camera.name, scene.name,
        with_path.empty() ? "no camera of this scene has one"
                          : "cameras with a path: " + with_path);
  }
  return camera;
}

// The converged reference's samples per pixel, or 0 where --reference-check is off.
int referenceCheckSpp(const CompareArgs& args) {
  if (args.reference_check != "auto" && args.reference_check != "on" &&
      args.reference_check != "off")
    throwInput("--reference-check {}: allowed auto|on|off", args.reference_check);
  if (args.reference_spp < 1 || args.reference_spp > 4096)
    throwInput("--reference-spp {}: allowed 1..4096", args.reference_spp);
  const bool on = args.reference_check == "on" ||
                  (args.reference_check == "auto" && args.reference == "raytrace");
  return on ? args.reference_spp : 0;
}

int runCompare(CompareArgs& args) {
  CompareRun run;
  run.size = parseSize(args.frame.size);
  run.settings = frameSettings(args.frame);
  run.ssaa = args.frame.ssaa;
  const int check_spp = referenceCheckSpp(args);
  run.display = displaySettings(args.frame);
  if (!(args.heatmap_max > 0.0f)) throwInput("--heatmap-max {}: must be > 0", args.heatmap_max);
  run.heatmap_max = args.heatmap_max;
  if (args.path_frames < 0 || args.path_frames > kMaxPathFrames)
    throwInput("--path-frames {}: allowed 0..{} (0: one view at --time)", args.path_frames,
               kMaxPathFrames);
  if (args.path_frames > 0 && args.time_option && args.time_option->count() > 0)
    throwInput(
        "--time cannot be combined with --path-frames: the frames' times are the path's (from its "
        "first key to its last)");
  findMethod(args.reference);
  run.methods = parseMethodList(args.methods);
  // The reference comes first and is always there.
  std::erase(run.methods, args.reference);
  run.methods.insert(run.methods.begin(), args.reference);
  run.params = args.params;
  warnUnusedParams(args.params, run.methods);
  Scene scene = loadSceneFromArgs(args.scene);
  run.scene = &scene;
  const CameraDesc* path_camera = args.path_frames > 0 ? &pathCamera(scene, args) : nullptr;
  run.size = imageSize(args.frame, scene.camera(args.scene.camera));
  const View view(scene.camera(args.scene.camera).at(args.scene.time), run.size);
  auto context = openHeadlessContext();
  run.context = context.get();
  run.frame_size = supersampledFrameSize(run.size, run.ssaa);
  ensureDirectory(args.output);  // once the input is known to be good: no folder left otherwise
  run.dir = args.output;
  const View frame_view(scene.camera(args.scene.camera).at(args.scene.time), run.frame_size);
  FrameRenderer renderer(scene, run.frame_size);
  run.renderer = &renderer;
  // Times stay at the output size: under --ssaa each method is timed in a run of its own there.
  std::unique_ptr<FrameRenderer> timing;
  if (run.ssaa > 1) timing = std::make_unique<FrameRenderer>(scene, run.size);
  run.timing_renderer = timing.get();

  CompareReport& report = run.report;
  report.scene = scene.name;
  report.scene_description = scene.description;
  report.size = run.size;
  report.order = run.settings.order;
  report.reference = args.reference;
  report.reference_info.ssaa = run.ssaa;
  report.reflector_names = reflectorNames(scene);
  run.layers = sceneLayers(scene);
  report.object_layers = objectLayers(scene, run.layers);
  report.timing =
      run.ssaa > 1
          ? fmt::format(
                "each method timed in a separate run at {}x{} without supersampling (the images "
                "and metrics come from the {}x{} frame)",
                run.size.x, run.size.y, run.frame_size.x, run.frame_size.y)
          : fmt::format("each method timed on the frames measured, at {}x{}", run.size.x,
                        run.size.y);
  report.device = context->info().renderer + " (" + context->info().version + ")";
  report.cpu = cpuDescription();
  report.triangles = scene.triangleCount();
  report.heatmap_max = args.heatmap_max;
  report.flip_ppd = FlipViewing{}.pixelsPerDegree();
  report.tonemap =
      fmt::format("{}, exposure {}", toneMapName(run.display.tonemap), run.display.exposure);

  if (path_camera)
    comparePath(run, *path_camera, args.path_frames, check_spp);
  else
    compareView(run, view, frame_view, args.scene.time, check_spp);
  writeCompareReport(args.output, report);
  spdlog::info("report: {}", (run.dir / "index.html").string());
  return 0;
}

}  // namespace

gpu::Clock methodClock(const CompareRun& run, const Method& method) {
  return method.info().gpu ? gpu::defaultClock(run.context->info().software) : gpu::Clock::kWall;
}

MethodReport describeMethod(const CompareRun& run, const std::string& name, const Method& method) {
  MethodReport m;
  m.name = name;
  m.description = method.info().description;
  m.order_rendered = method.orderRendered(run.settings.order);
  if (m.order_rendered < run.settings.order)
    m.note = fmt::format("order {} only ({} requested)", m.order_rendered, run.settings.order);
  m.stats = method.stats();
  m.fallback = method.fallbackReason();
  if (!m.fallback.empty()) m.note = "drawn by envmap: the driver refused it (" + m.fallback + ")";
  return m;
}

MapFiles writeMaps(const CompareRun& run, const std::string& stem, const Image& shown,
                   const Image& reference, const Image2D<float>& flip) {
  MapFiles files{stem + ".png", stem + ".err.png", stem + ".flip.png"};
  writePng((run.dir / files.image).string(), shown);
  writePng((run.dir / files.error_image).string(),
           heatmap(absoluteError(shown, reference), run.heatmap_max));
  // FLIP is in [0, 1] by construction: a fixed scale, comparable across methods and reports.
  writePng((run.dir / files.flip_image).string(), heatmap(flip, 1.0f));
  return files;
}

Command addCompareCommand(CLI::App& parent) {
  std::shared_ptr<CompareArgs> args;
  Command cmd = renderingCommand(
      parent, "compare", "render a scene with several methods and measure each against a reference",
      args);
  args->time_option = cmd.app->get_option("--time");
  std::string names;
  for (const std::string& n : methodNames()) names += (names.empty() ? "" : ",") + n;
  addDefaulted(cmd.app, "--methods", args->methods, "all, or a comma-separated list of: " + names);
  addDefaulted(cmd.app, "--reference", args->reference,
               "the method the others are measured against (e.g. planar: exact for planar "
               "mirrors, and much faster than the ray tracer along a path)");
  addDefaulted(cmd.app, "--path-frames", args->path_frames,
               "render N frames along the camera's path (--camera; equal steps from its first "
               "key to its last), each method keeping its state from frame to frame; 0: one "
               "view at --time (0..100000)");
  addFrameOptions(cmd.app, args->frame);
  args->frame.ssaa = 4;  // quality is measured with matched supersampling unless told otherwise
  addSsaaOption(cmd.app, args->frame);
  addDefaulted(cmd.app, "--reference-check", args->reference_check,
               "also render a converged reference (--reference-spp stratified samples a "
               "pixel) and report how far the matched reference is from it: auto (on when "
               "the reference is the ray tracer), on, off");
  addDefaulted(cmd.app, "--reference-spp", args->reference_spp,
               "samples per pixel of the converged reference (1..4096)");
  cmd.app->add_option("-o,--output", args->output, "report directory")->required();
  addDefaulted(cmd.app, "--heatmap-max", args->heatmap_max,
               "error shown as the brightest heat-map colour (display units, > 0)");
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runCompare(*args); };
  return cmd;
}

}  // namespace mirage::app
