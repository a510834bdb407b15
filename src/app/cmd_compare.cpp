// `mirage compare`: every chosen method against the ray-traced reference on one view: images,
// absolute-error and FLIP maps, PSNR/SSIM/FLIP (all pixels and reflector pixels) and times, as
// DIR/index.html and DIR/metrics.json.
#include <filesystem>

#include <spdlog/spdlog.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/error.h"
#include "eval/flip.h"
#include "eval/heatmap.h"
#include "eval/report.h"
#include "methods/frame.h"

namespace mirage::app {

namespace {

struct CompareArgs {
  SceneArgs scene;
  FrameArgs frame;
  std::string methods = "all";
  std::string output;
  float heatmap_max = 0.25f;
  std::map<std::string, std::string> params;
};

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

int runCompare(const CompareArgs& args) {
  ivec2 size = parseSize(args.frame.size);
  FrameSettings settings = frameSettings(args.frame);
  DisplaySettings display = displaySettings(args.frame);
  if (!(args.heatmap_max > 0.0f)) throwInput("--heatmap-max {}: must be > 0", args.heatmap_max);
  std::vector<std::string> methods = parseMethodList(args.methods);
  // The reference comes first and is always there.
  std::erase(methods, std::string("raytrace"));
  methods.insert(methods.begin(), "raytrace");
  warnUnusedParams(args.params, methods);
  Scene scene = loadSceneFromArgs(args.scene);
  View view(scene.camera(args.scene.camera), size);
  ensureDirectory(args.output);
  auto context = openHeadlessContext();
  FrameRenderer renderer(scene, size);

  CompareReport report;
  report.scene = scene.name;
  report.scene_description = scene.description;
  report.size = size;
  report.order = settings.order;
  report.device = context->info().renderer + " (" + context->info().version + ")";
  report.cpu = cpuDescription();
  report.triangles = scene.triangleCount();
  report.heatmap_max = args.heatmap_max;
  report.flip_ppd = FlipViewing{}.pixelsPerDegree();
  report.tonemap = fmt::format("{}, exposure {}", toneMapName(display.tonemap), display.exposure);

  Image reference_display;
  IdImage mask;
  std::filesystem::path dir(args.output);
  for (const std::string& name : methods) {
    auto method = renderer.createMethod(name, args.params, settings);
    gpu::Clock clock =
        method->info().gpu ? gpu::defaultClock(context->info().software) : gpu::Clock::kWall;
    Rendered r = renderTwice(renderer, *method, view, args.scene.time, settings, clock);
    Image shown = toDisplay(r.frame.color, display);
    if (name == "raytrace") {
      reference_display = shown;
      mask = r.frame.ids;
    }
    MethodReport m;
    m.name = name;
    m.description = method->info().description;
    Image2D<float> flip;
    m.metrics = compareImages(shown, reference_display, mask, &flip);
    m.ms = r.ms;
    m.first_ms = r.first_ms;
    m.order_rendered = method->orderRendered(settings.order);
    if (m.order_rendered < settings.order)
      m.note = fmt::format("order {} only ({} requested)", m.order_rendered, settings.order);
    m.stats = method->stats();
    m.image = name + ".png";
    m.error_image = name + ".err.png";
    m.flip_image = name + ".flip.png";
    writePng((dir / m.image).string(), shown);
    writePng((dir / m.error_image).string(),
             heatmap(absoluteError(shown, reference_display), args.heatmap_max));
    // FLIP is in [0, 1] by construction: a fixed scale, comparable across methods and reports.
    writePng((dir / m.flip_image).string(), heatmap(flip, 1.0f));
    spdlog::info(
        "{:>16}: PSNR {:6.2f} dB (reflector {:6.2f}), SSIM {:.4f}, FLIP {:.4f} (reflector {:.4f}), "
        "{:8.2f} ms",
        name, m.metrics.psnr, m.metrics.psnr_reflector, m.metrics.ssim, m.metrics.flip,
        m.metrics.flip_reflector, m.ms);
    report.methods.push_back(std::move(m));
  }
  writeCompareReport(args.output, report);
  spdlog::info("report: {}", (dir / "index.html").string());
  return 0;
}

}  // namespace

Command addCompareCommand(CLI::App& parent) {
  auto args = std::make_shared<CompareArgs>();
  Command cmd;
  cmd.app = parent.add_subcommand(
      "compare", "render a scene with several methods and measure each against the ray tracer");
  addSceneOptions(cmd.app, args->scene);
  std::string names;
  for (const std::string& n : methodNames()) names += (names.empty() ? "" : ",") + n;
  cmd.app->add_option("--methods", args->methods, "all, or a comma-separated list of: " + names)
      ->capture_default_str();
  addFrameOptions(cmd.app, args->frame);
  cmd.app->add_option("-o,--output", args->output, "report directory")->required();
  cmd.app
      ->add_option("--heatmap-max", args->heatmap_max,
                   "error shown as the brightest heat-map colour (display units, > 0)")
      ->capture_default_str();
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runCompare(*args); };
  return cmd;
}

}  // namespace mirage::app
