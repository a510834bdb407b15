// Options and steps that several commands share: the scene, the image size, the reflection
// order, the display transform and every method's parameters.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/display.h"
#include "core/frame_settings.h"
#include "gpu/context.h"
#include "scene/scene_loader.h"

namespace mirage::app {

struct SceneArgs {
  std::string scene;
  int reflectors = -1;
  int objects = -1;
  std::string camera;
  std::string camera_path;  // a camera file (scene/camera_file.h), used instead of the scene's
  std::string stage;        // model files: auto|on|off (StageMode); empty: not given
  float time = 0.0f;
  CLI::Option* time_option = nullptr;  // to tell a given --time from the default
  std::string max_memory = "4G";       // what one input file may make us allocate
};

struct FrameArgs {
  std::string size = "720x512";
  CLI::Option* size_option = nullptr;  // to tell a given --size from the default
  int order = 2;
  std::string mip = "on";
  float exposure = 1.0f;
  std::string tonemap = "aces";
  int ssaa = 1;  // --ssaa N: render N x N sub-pixels per output pixel (render, compare, view)
};

// What every rendering command (render, compare, bench, view) reads: the scene, the frame, and
// the methods' parameters.
struct RenderingArgs {
  SceneArgs scene;
  FrameArgs frame;
  std::map<std::string, std::string> params;  // method parameters given, by name
};

// An option whose default --help shows.
template <typename T>
CLI::Option* addDefaulted(CLI::App* app, const std::string& name, T& value,
                          const std::string& help) {
  return app->add_option(name, value, help)->capture_default_str();
}

void addSceneOptions(CLI::App* app, SceneArgs& args);
void addFrameOptions(CLI::App* app, FrameArgs& args);
// --ssaa N (1..8) for the commands that measure or show quality (bench times the output size).
void addSsaaOption(CLI::App* app, FrameArgs& args);
// Registers --<name> for every method parameter; given values land in `values`.
void addMethodParamOptions(CLI::App* app, std::map<std::string, std::string>& values);

// A rendering subcommand of `parent` with the scene's options first: its options write into a
// new `args`, which the command's run callback is to keep alive.
template <class Args>
Command renderingCommand(CLI::App& parent, const std::string& name, const std::string& help,
                         std::shared_ptr<Args>& args) {
  args = std::make_shared<Args>();
  Command cmd;
  cmd.app = parent.add_subcommand(name, help);
  addSceneOptions(cmd.app, args->scene);
  return cmd;
}

// "WxH" with 1 <= W, H <= 16384; throws InputError naming the option.
ivec2 parseSize(const std::string& text);
// The image size for `camera`: --size when given; else the default's width and, for a camera
// with an aspect of its own (a glTF camera's aspectRatio), the height that aspect gives.
ivec2 imageSize(const FrameArgs& args, const CameraDesc& camera);
// The scene; with --camera-path, the file's camera becomes its first (the one every command
// uses when --camera is not given: the two exclude each other), and the file's time (a
// screenshot's) becomes args.time unless --time was given.
Scene loadSceneFromArgs(SceneArgs& args);
// The reflection order, mip setting and --ssaa (checked: 1..8) as a method sees them.
FrameSettings frameSettings(const FrameArgs& args);
// The size the frame is rendered at for an output of `size` under --ssaa (the current context's
// limits and --max-memory checked: InputError naming --ssaa and --size).
ivec2 supersampledFrameSize(ivec2 size, int ssaa);
DisplaySettings displaySettings(const FrameArgs& args);
std::unique_ptr<gpu::Context> openHeadlessContext();
// Warns about given method parameters that none of `methods` uses.
void warnUnusedParams(const std::map<std::string, std::string>& values,
                      const std::vector<std::string>& methods);
// The CPU model from /proc/cpuinfo and the core count.
std::string cpuDescription();
// Creates `path` as a directory (and parents); InputError if that is impossible.
void ensureDirectory(const std::string& path);

}  // namespace mirage::app
