// `mirage view`: the interactive viewer (viewer/viewer.h).
#include "app/cli_common.h"
#include "app/commands.h"
#include "core/error.h"
#include "viewer/viewer.h"

namespace mirage::app {

namespace {

struct ViewArgs {
  SceneArgs scene;
  FrameArgs frame;
  std::string method = "envmap";
  int frames = 0;
  std::string screenshot;
  bool no_vsync = false;
  std::map<std::string, std::string> params;
};

int runView(const ViewArgs& args) {
  ViewerOptions o;
  o.size = parseSize(args.frame.size);
  o.settings = frameSettings(args.frame);
  o.display = displaySettings(args.frame);
  findMethod(args.method);
  if (args.frames < 0 || args.frames > 1000000)
    throwInput("--frames {}: allowed 0..1000000 (0: until the window is closed)", args.frames);
  if (!args.screenshot.empty() && args.frames == 0)
    throwInput("--screenshot {}: needs --frames N (the frame to write)", args.screenshot);
  warnUnusedParams(args.params, methodNames());
  Scene scene = loadSceneFromArgs(args.scene);
  o.camera = scene.camera(args.scene.camera).at(args.scene.time);
  o.time = args.scene.time;
  o.method = args.method;
  o.params = args.params;
  o.frames = args.frames;
  o.screenshot = args.screenshot;
  o.vsync = !args.no_vsync;
  return runViewer(scene, o);
}

}  // namespace

Command addViewCommand(CLI::App& parent) {
  auto args = std::make_shared<ViewArgs>();
  Command cmd;
  cmd.app = parent.add_subcommand(
      "view", "the interactive viewer: any method, an orbit camera, live method and order");
  addSceneOptions(cmd.app, args->scene);
  cmd.app->add_option("--method", args->method, "the method shown first")->capture_default_str();
  addFrameOptions(cmd.app, args->frame);
  cmd.app->add_option("--frames", args->frames,
                      "render this many frames, then exit (0..1000000; 0: until closed)");
  cmd.app->add_option("--screenshot", args->screenshot,
                      "with --frames: write the last frame here (.png display, .exr linear)");
  cmd.app->add_flag("--no-vsync", args->no_vsync, "render as fast as possible");
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runView(*args); };
  return cmd;
}

}  // namespace mirage::app
