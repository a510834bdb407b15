// `mirage render`: one image of a scene with one method, or a sequence of frames (--frames N at
// --fps F from --time: PNG/EXR frames, or an MP4 through ffmpeg).
#include <filesystem>

#include <spdlog/spdlog.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/video.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/timer.h"
#include "methods/frame.h"

namespace mirage::app {

namespace {

namespace fs = std::filesystem;

struct RenderArgs : RenderingArgs {
  std::string method;
  std::string output;
  int frames = 1;
  double fps = 30.0;
};

// A temporary folder for an MP4's PNG frames, removed with everything in it.
class TempFolder {
 public:
  explicit TempFolder(const fs::path& near) {
    std::string pattern = (near / ".mirage-frames-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throwInput("-o: cannot create a folder for the frames beside {}", near.string());
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

int runRender(RenderArgs& args) {
  ivec2 size = parseSize(args.frame.size);
  FrameSettings settings = frameSettings(args.frame);
  DisplaySettings display = displaySettings(args.frame);
  findMethod(args.method);
  if (args.frames < 1 || args.frames > 100000)
    throwInput("--frames {}: allowed 1..100000", args.frames);
  if (!(args.fps > 0.0 && args.fps <= 1000.0)) throwInput("--fps {}: allowed (0, 1000]", args.fps);
  const fs::path out(args.output);
  const std::string ext = out.extension().string();
  const bool mp4 = ext == ".mp4";
  if (ext != ".png" && ext != ".exr" && !mp4)
    throwInput("-o {}: the output must end in .png, .exr{}", args.output,
               args.frames > 1 ? " or .mp4 (frames through ffmpeg)" : "");
  if (mp4 && args.frames < 2) throwInput("-o {}: an MP4 needs --frames 2 or more", args.output);
  std::string ffmpeg;
  if (mp4) {
    ffmpeg = findFfmpeg();
    if (ffmpeg.empty())
      throwInput(
          "-o {}: ffmpeg was not found on PATH; install it (apt-get install ffmpeg) or "
          "write PNG frames (-o frames.png)",
          args.output);
  }
  warnUnusedParams(args.params, {args.method});
  Scene scene = loadSceneFromArgs(args.scene);
  const CameraDesc& camera = scene.camera(args.scene.camera);
  size = imageSize(args.frame, camera);
  auto context = openHeadlessContext();
  // --ssaa N: the frame is N x N times the output and box-filtered down to it.
  const int ssaa = args.frame.ssaa;
  const ivec2 frame_size = supersampledFrameSize(size, ssaa);
  FrameRenderer renderer(scene, frame_size);
  auto method = renderer.createMethod(args.method, args.params, settings);

  std::unique_ptr<TempFolder> folder;
  if (mp4) folder = std::make_unique<TempFolder>(out.has_parent_path() ? out.parent_path() : ".");
  const std::string frame_name = mp4 ? (folder->path() / "frame.png").string() : args.output;
  Progress progress("render", args.frames > 1 ? size_t(args.frames) : 0);
  Stopwatch watch;
  double first_ms = 0.0;
  for (int i = 0; i < args.frames; ++i) {
    // Each frame at its own time: the scene and the camera's path move together.
    const float time = args.scene.time + float(double(i) / args.fps);
    Stopwatch frame_watch;
    renderer.render(*method, View(camera.at(time), frame_size), time, settings);
    RenderedFrame frame = downsample(renderer.read(), ssaa);
    if (i == 0) first_ms = frame_watch.ms();
    writeImage(args.frames > 1 ? frameFileName(frame_name, i, args.frames) : frame_name,
               frame.color, display);
    progress.advance();
  }
  if (mp4) encodeMp4(ffmpeg, framePattern(frame_name, args.frames), args.fps, args.output);
  int order = method->orderRendered(settings.order);
  const std::string fallback = method->fallbackReason();
  const std::string order_text =
      fmt::format("order {}{}{}", order,
                  order < settings.order ? fmt::format(", {} requested", settings.order) : "",
                  fallback.empty() ? "" : ", drawn by envmap: the driver refused it");
  if (args.frames == 1)
    spdlog::info("{}: {} on {} at {}x{}{} in {:.1f} ms ({})", args.output, args.method, scene.name,
                 size.x, size.y,
                 ssaa > 1 ? fmt::format(" (--ssaa {}: {}x{} sub-pixels)", ssaa, ssaa, ssaa) : "",
                 first_ms, order_text);
  else
    spdlog::info("{}: {} frames of {} on {} at {}x{}, t = {}..{} s at {} fps, in {:.1f} s ({})",
                 mp4 ? args.output : frameFileName(args.output, 0, args.frames) + "...",
                 args.frames, args.method, scene.name, size.x, size.y, args.scene.time,
                 args.scene.time + float(double(args.frames - 1) / args.fps), args.fps,
                 watch.ms() / 1000.0, order_text);
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& parent) {
  std::shared_ptr<RenderArgs> args;
  Command cmd = renderingCommand(
      parent, "render", "render one image of a scene with one method, or a sequence of frames",
      args);
  cmd.app->add_option("--method", args->method, "the method (see `mirage compare --help`)")
      ->required();
  addFrameOptions(cmd.app, args->frame);
  addSsaaOption(cmd.app, args->frame);
  cmd.app
      ->add_option("-o,--output", args->output,
                   "output image: .png (display) or .exr (linear); with --frames N > 1 frame "
                   "i goes to <name>_<i>.<ext>, or all of them into one .mp4 (needs ffmpeg)")
      ->required();
  addDefaulted(cmd.app, "--frames", args->frames,
               "render N frames (1..100000), frame i at --time + i / --fps");
  addDefaulted(cmd.app, "--fps", args->fps, "frames per second of a sequence (0..1000]");
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runRender(*args); };
  return cmd;
}

}  // namespace mirage::app
