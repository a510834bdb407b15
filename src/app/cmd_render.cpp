// `mirage render`: one image of a scene with one method.
#include <spdlog/spdlog.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/error.h"
#include "core/timer.h"
#include "methods/frame.h"

namespace mirage::app {

namespace {

struct RenderArgs {
  SceneArgs scene;
  FrameArgs frame;
  std::string method;
  std::string output;
  std::map<std::string, std::string> params;
};

int runRender(const RenderArgs& args) {
  ivec2 size = parseSize(args.frame.size);
  FrameSettings settings = frameSettings(args.frame);
  DisplaySettings display = displaySettings(args.frame);
  findMethod(args.method);
  warnUnusedParams(args.params, {args.method});
  Scene scene = loadSceneFromArgs(args.scene);
  View view(scene.camera(args.scene.camera).at(args.scene.time), size);
  auto context = openHeadlessContext();
  FrameRenderer renderer(scene, size);
  auto method = renderer.createMethod(args.method, args.params, settings);
  Stopwatch watch;
  renderer.render(*method, view, args.scene.time, settings);
  RenderedFrame frame = renderer.read();
  double ms = watch.ms();
  writeImage(args.output, frame.color, display);
  int order = method->orderRendered(settings.order);
  spdlog::info("{}: {} on {} at {}x{} in {:.1f} ms (order {}{})", args.output, args.method,
               scene.name, size.x, size.y, ms, order,
               order < settings.order ? fmt::format(", {} requested", settings.order) : "");
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& parent) {
  auto args = std::make_shared<RenderArgs>();
  Command cmd;
  cmd.app = parent.add_subcommand("render", "render one image of a scene with one method");
  addSceneOptions(cmd.app, args->scene);
  cmd.app->add_option("--method", args->method, "the method (see `mirage compare --help`)")
      ->required();
  addFrameOptions(cmd.app, args->frame);
  cmd.app->add_option("-o,--output", args->output, "output image: .png (display) or .exr (linear)")
      ->required();
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runRender(*args); };
  return cmd;
}

}  // namespace mirage::app
