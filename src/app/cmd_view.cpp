// `mirage view`: the interactive viewer (viewer/viewer.h).
#include <filesystem>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/error.h"
#include "scene/builtin_scenes.h"
#include "scene/camera_file.h"
#include "viewer/input.h"
#include "viewer/viewer.h"

namespace mirage::app {

namespace {

struct ViewArgs : RenderingArgs {
  std::string method = "envmap";
  int frames = 0;
  std::string screenshot;
  bool screenshot_panel = false;
  std::string screenshot_dir;
  bool no_vsync = false;
  bool pause = false;
  std::string events, record_events, record_path, play_path, report;
  std::string truth = "off";
  bool heatmap = false;
  int truth_divisor = 2;
};

// The viewer's input and output files beyond its screenshots, each an option of a path.
struct PathOption {
  const char* name;
  std::string ViewArgs::*field;
  const char* help;
};
const PathOption kPathOptions[] = {
    {"--events", &ViewArgs::events,
     "an event script (keys, buttons, cursor, wheel by frame) to replay"},
    {"--record-events", &ViewArgs::record_events,
     "write the window's input here as an event script at exit"},
    {"--record-path", &ViewArgs::record_path,
     "record the camera from the start into this camera file (written at exit or when P stops "
     "the recording)"},
    {"--play-path", &ViewArgs::play_path,
     "play this camera file's path from the start (L plays it again)"},
    {"--report", &ViewArgs::report,
     "at exit, write a JSON report: frame times, GL object counts at the first and last frame, "
     "the camera, the reference's PSNR"},
};

TruthMode parseTruthMode(const std::string& text) {
  if (const auto mode = findChoice<TruthMode>(kTruthModes, text)) return *mode;
  throwInput("--truth {}: allowed {}", text, choiceNames<TruthMode>(kTruthModes, "|"));
}

int runView(ViewArgs& args) {
  ViewerOptions o;
  o.size = parseSize(args.frame.size);
  o.settings = frameSettings(args.frame);
  o.display = displaySettings(args.frame);
  findMethod(args.method);
  if (args.frames < 0 || args.frames > 1000000)
    throwInput("--frames {}: allowed 0..1000000 (0: until the window is closed)", args.frames);
  if (!args.screenshot.empty() && args.frames == 0)
    throwInput("--screenshot {}: needs --frames N (the frame to write)", args.screenshot);
  if (!args.screenshot.empty() && !args.screenshot.ends_with(".png") &&
      !args.screenshot.ends_with(".exr"))
    throwInput("--screenshot {}: must end in .png or .exr", args.screenshot);
  if (args.truth_divisor < 1 || args.truth_divisor > 8)
    throwInput("--truth-resolution {}: allowed 1..8 (the reference at 1/n of the frame's size)",
               args.truth_divisor);
  o.output.truth = parseTruthMode(args.truth);
  o.output.heatmap = args.heatmap;
  warnUnusedParams(args.params, methodNames());
  Scene scene = loadSceneFromArgs(args.scene);
  // Files are read before a window opens: a bad one is exit 2 with its name, display or not.
  if (!args.events.empty()) o.events = loadEventScript(args.events);
  o.camera_index = 0;
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    if (scene.cameras[i].name == args.scene.camera) o.camera_index = int(i);
  o.camera = scene.camera(args.scene.camera).at(args.scene.time);
  o.size = imageSize(args.frame, scene.camera(args.scene.camera));
  o.time = args.scene.time;
  o.play = scene.animated() && !args.pause;
  o.method = args.method;
  o.params = args.params;
  o.frames = args.frames;
  o.screenshot = args.screenshot;
  o.screenshot_panel = args.screenshot_panel;
  o.screenshot_dir = args.screenshot_dir;
  if (o.screenshot_dir.empty() && !isBuiltinScene(args.scene.scene)) {
    // Next to the scene file (or the mesh) when there is one.
    const std::filesystem::path file(args.scene.scene);
    if (std::filesystem::exists(file)) o.screenshot_dir = file.parent_path().string();
  }
  if (!o.screenshot_dir.empty()) ensureDirectory(o.screenshot_dir);
  o.vsync = !args.no_vsync;
  o.record_events = args.record_events;
  o.record_path = args.record_path;
  if (!args.play_path.empty()) {
    o.play_path = loadCameraFile(args.play_path).camera;
    if (o.play_path->path.empty())
      throwInput("--play-path {}: the camera has no path (it needs \"path\" keys)", args.play_path);
  }
  o.report = args.report;
  o.truth_divisor = args.truth_divisor;
  return runViewer(scene, o);
}

}  // namespace

Command addViewCommand(CLI::App& parent) {
  std::shared_ptr<ViewArgs> args;
  Command cmd = renderingCommand(
      parent, "view",
      "the interactive viewer: any method, live parameters, fly/orbit camera, scene time, the "
      "ray-traced ground truth beside the frame",
      args);
  addDefaulted(cmd.app, "--method", args->method, "the method shown first");
  addFrameOptions(cmd.app, args->frame);
  addSsaaOption(cmd.app, args->frame);
  cmd.app->add_flag("--pause", args->pause, "start with the scene's time stopped");
  cmd.app->add_option("--frames", args->frames,
                      "render this many frames (1/60 s steps), then exit (0..1000000; 0: until "
                      "the window is closed)");
  cmd.app->add_option("--screenshot", args->screenshot,
                      "with --frames: write the last frame here (.png as shown, .exr linear) and "
                      "its camera beside it (<name>.camera.json)");
  cmd.app->add_flag("--screenshot-panel", args->screenshot_panel,
                    "the --screenshot .png with the panel drawn over it");
  cmd.app->add_option("--screenshot-dir", args->screenshot_dir,
                      "where F12 writes screenshots and P camera paths (default: next to the "
                      "scene file, or the current folder)");
  for (const PathOption& o : kPathOptions) cmd.app->add_option(o.name, (*args).*o.field, o.help);
  addDefaulted(cmd.app, "--truth", args->truth,
               "the ground truth at the start: " + choiceNames<TruthMode>(kTruthModes, "|"));
  cmd.app->add_flag("--heatmap", args->heatmap, "start with the error heat map on");
  addDefaulted(cmd.app, "--truth-resolution", args->truth_divisor,
               "the reference's resolution, 1/n of the frame's (1..8)");
  cmd.app->add_flag("--no-vsync", args->no_vsync, "render as fast as possible");
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runView(*args); };
  return cmd;
}

}  // namespace mirage::app
