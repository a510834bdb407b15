// `mirage advise`: each reflector's technique chosen from measured error and cost within a frame
// budget (app/advise.h, docs/advise.md).
#include <spdlog/spdlog.h>

#include "app/advise.h"
#include "app/advise_report.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "methods/assignment.h"
#include "methods/method.h"

namespace mirage::app {

namespace {

struct AdviseArgs : RenderingArgs {
  std::string budget = "4x";
  int views = 2;
  int frames = 5;
  std::string methods = "all";
  std::string out = "advise";
};

std::vector<std::string> assignableMethods(const std::string& list) {
  std::vector<std::string> out;
  for (const std::string& name : parseMethodList(list)) {
    if (assignable(findMethod(name).info))
      out.push_back(name);
    else if (list != "all")
      throwInput("--methods: '{}' cannot be assigned to reflectors (it draws whole frames)", name);
  }
  return out;
}

int runAdvise(AdviseArgs& args) {
  if (args.views < 0 || args.views > 64) throwInput("--views {}: allowed 0..64", args.views);
  if (args.frames < 1 || args.frames > 1000)
    throwInput("--frames {}: allowed 1..1000", args.frames);
  AdviseSetup setup;
  setup.size = parseSize(args.frame.size);
  setup.settings = frameSettings(args.frame);
  setup.ssaa = args.frame.ssaa;
  setup.display = displaySettings(args.frame);
  setup.params = args.params;
  setup.frames = args.frames;
  setup.budget = parseBudget(args.budget);
  setup.candidates = candidateGrid(assignableMethods(args.methods));
  Scene scene = loadSceneFromArgs(args.scene);
  setup.size = imageSize(args.frame, scene.camera(args.scene.camera));
  setup.views = calibrationViews(scene, args.scene.time, args.views);
  ensureDirectory(args.out);
  auto context = openHeadlessContext();
  supersampledFrameSize(setup.size, setup.ssaa);
  spdlog::info("advise: {} candidates on {} reflectors of '{}' over {} views",
               setup.candidates.size(), scene.reflectorInstances().size(), scene.name,
               setup.views.size());
  const Advice a = advise(scene, setup);

  const std::string dir = args.out + "/";
  const std::string flags = "--method mixed --assign '" + assignText(a.rules) + "'";
  writeFileAtomic(dir + "advice.json", adviceJson(a, scene.name).dump(2) + "\n");
  writeFileAtomic(dir + "assignment.json", reflectionsJson(a.rules).dump(2) + "\n");
  writeFileAtomic(dir + "assign.txt", flags + "\n");
  writeFileAtomic(dir + "report.html", adviceHtml(a, scene.name));
  spdlog::info("advise: {}", flags);
  if (!a.failed.empty())
    spdlog::warn("advise: {} of {} candidates failed and were left out (advice.json, \"failed\")",
                 a.failed.size(), setup.candidates.size());
  spdlog::info(
      "advise: predicted {:.2f} dB in {:.2f} ms, measured {:.2f} dB in {:.2f} ms "
      "(budget {:.2f} ms); {}report.html",
      a.psnr(a.predicted_sse), a.predicted_ms, a.psnr(a.measured_sse), a.measured_ms, a.budget_ms,
      dir);
  if (a.fits && a.measured_ms > a.budget_ms)
    spdlog::warn(
        "advise: the composite measured {:.2f} ms, over the budget of {:.2f} ms that "
        "its parts' times predicted it within ({:.2f} ms)",
        a.measured_ms, a.budget_ms, a.predicted_ms);
  if (!a.fits)
    throwInput(
        "--budget {}: nothing fits in {:.2f} ms; the cheapest assignment ({}) costs {:.2f} "
        "ms (its report is in {})",
        args.budget, a.budget_ms, assignText(a.rules), a.predicted_ms, args.out);
  return 0;
}

}  // namespace

Command addAdviseCommand(CLI::App& parent) {
  std::shared_ptr<AdviseArgs> args;
  Command cmd = renderingCommand(
      parent, "advise",
      "choose each reflector's technique from measured error and cost within a frame budget", args);
  addDefaulted(cmd.app, "--budget", args->budget,
               "frame budget: milliseconds (e.g. 25), or a multiple of the none frame's median "
               "measured in the same run (e.g. 4x)");
  addDefaulted(cmd.app, "--views", args->views,
               "calibration views along the scene's camera path besides its cameras (0..64)");
  addDefaulted(cmd.app, "--frames", args->frames,
               "timed frames per view and candidate; the cost is their median (1..1000)");
  addDefaulted(cmd.app, "--methods", args->methods,
               "the methods tried (with their grids): all, or a comma-separated list");
  addDefaulted(cmd.app, "-o,--out", args->out,
               "directory for advice.json, assignment.json, "
               "assign.txt and report.html");
  args->frame.size = "360x256";
  args->frame.ssaa = 4;  // quality is measured with matched supersampling
  addFrameOptions(cmd.app, args->frame);
  addSsaaOption(cmd.app, args->frame);
  addMethodParamOptions(cmd.app, args->params);
  cmd.run = [args] { return runAdvise(*args); };
  return cmd;
}

}  // namespace mirage::app
